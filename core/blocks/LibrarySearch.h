// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "BlockLibrary.h"
#include "lang/Diagnostic.h"

#include <QString>
#include <QStringList>

#include <vector>

// Where libraries come from (docs/block-libraries.md, "Finding libraries"):
// the standard libraries shipped with the program, and user libraries in
// the project's folder and given by name on the command line (manual 12.1).
namespace rs::blocks {

// The file name extension of a library, without the dot.
inline constexpr const char* kLibraryExtension = "rslib";

// The folders searched for standard libraries, first first: beside the
// binary (a build tree), ../share/rungsmith/libraries from the binary (an
// installation under any prefix), then /usr/share/rungsmith/libraries.
// Folders that do not exist are left out, and each folder appears once.
QStringList standardLibraryFolders(const QString& executableDir);

// The .rslib files of a folder, sorted by name, so the order never depends on
// the file system.
QStringList libraryFilesIn(const QString& folder);

enum class LibraryOrigin { Standard, User };

struct LoadedLibrary {
    BlockLibrary library;
    QString path;
    LibraryOrigin origin = LibraryOrigin::Standard;
};

// A problem with one library file: it could not be read, or its text has
// problems (each with line and column).
struct LibraryFileProblem {
    QString path;
    QString readError; // empty when the file was read
    lang::Diagnostics diagnostics;
};

struct LibrarySet {
    std::vector<LoadedLibrary> libraries;
    std::vector<LibraryFileProblem> problems;

    bool ok() const;
    const LoadedLibrary* findLibrary(std::string_view name) const;
    // The first library, in search order, that defines the block.
    const LoadedLibrary* libraryOfBlock(std::string_view blockName) const;
};

// Reads a library file and adds it. A library with errors is not added; a
// library whose name an earlier one already has is not added either (the
// earlier one wins, which is how a user library cannot replace a standard
// one by accident: the warning says so).
void addLibraryFile(LibrarySet& set, const QString& path, LibraryOrigin origin);

// The standard libraries of these folders, then the user libraries of the
// project's folder (when given), then the files given.
LibrarySet loadLibraries(const QStringList& standardFolders, const QString& projectFolder,
                         const QStringList& userFiles);

} // namespace rs::blocks
