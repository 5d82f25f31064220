// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"
#include "TextSink.h"
#include "lang/Diagnostic.h"

#include <QString>

#include <functional>
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
// `expectedSize`: the size the text is likely to have (that of the file the
// project was read from), kept for it at once.
std::string writeProject(const Project& project, std::size_t expectedSize = 0);

struct FileText {
    std::string text;
    QString error; // "cannot read FILE: reason" when reading failed
};

// The most any reader takes from one file: far above the largest real project
// (the 32-unit generated plant is 2.4 MB) and low enough that an endless input
// such as /dev/zero is refused with a message instead of exhausting memory.
inline constexpr qint64 kMaxTextFileBytes = 64 * 1024 * 1024;

// Reads a UTF-8 text file of at most maxBytes. A leading UTF-8 byte-order mark
// is dropped, so columns count as an editor shows them; a UTF-16 or UTF-32
// mark is refused with a message, since every reader expects UTF-8.
FileText readTextFile(const QString& path, qint64 maxBytes = kMaxTextFileBytes);

// Writes through QSaveFile: the old file stays intact unless the whole new
// text reached the disk. Returns an error message, empty on success.
QString writeTextFile(const QString& path, std::string_view text);

// The same for text made while it is written: `write` gives it to the sink in
// pieces. Should `write` throw, the old file stays and the exception goes on.
QString writeTextFile(const QString& path, const std::function<void(const TextSink&)>& write);

} // namespace rs::project
