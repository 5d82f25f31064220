// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "blocks/ProjectInstances.h"

#include "Invocation.h"
#include "lang/Diagnostic.h"
#include "project/Project.h"

#include <QString>
#include <QStringList>

// How every verb that takes FILE.sps reads it: the text, then its block
// instances expanded from the libraries (the standard ones, the .rslib files
// in the project's folder and those given with --lib).
namespace rs::cli {

// Whether a --lib value is a library file (one that exists, or any name with
// the library extension) rather than a library's name.
bool isLibraryFile(const QString& value);

// The --lib values that are library files.
QStringList libraryFiles(const Invocation& invocation);

struct LoadedProject {
    project::Project project;
    std::string text;              // as read
    lang::Diagnostics diagnostics; // of the text and its block instances, by place
    int status = 0;                // UsageOrIo when the project or a library cannot be read
    blocks::LibraryPlaces places;  // where its libraries were found

    bool ok() const { return status == 0 && lang::errorCount(diagnostics) == 0; }
};

// Problems with the libraries are printed here; the project's diagnostics are
// left to the verb.
LoadedProject loadProject(const QString& path, const QStringList& libraryFiles);

void printDiagnostics(const QString& path, const lang::Diagnostics& diagnostics);

} // namespace rs::cli
