#pragma once

#include "Project.h"
#include "lang/Diagnostic.h"

#include <QString>

#include <optional>
#include <string>
#include <string_view>

namespace rs::project {

struct ProjectReadResult {
    Project project;
    lang::Diagnostics diagnostics;

    bool ok() const { return lang::errorCount(diagnostics) == 0; }
};

// Parses project text: the program, its names resolved, and the ";@" records
// taken out of the comments into the project's fields.
ProjectReadResult readProject(std::string_view text);

// The canonical project text; readProject(writeProject(p)) gives p back and
// writing that again gives the same bytes.
std::string writeProject(const Project& project);

struct FileText {
    std::string text;
    QString error; // "cannot read FILE: reason" when reading failed
};

FileText readTextFile(const QString& path);

// Writes through QSaveFile: the old file stays intact unless the whole new
// text was written. Returns an error message, empty on success.
QString writeTextFile(const QString& path, std::string_view text);

} // namespace rs::project
