// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "LibrarySearch.h"
#include "compiler/Compiler.h"
#include "lang/Ast.h"
#include "lang/Diagnostic.h"
#include "project/ProjectFile.h"

#include <functional>
#include <string_view>

// The block instances of a whole program (blocks.md).
namespace rs::blocks {

// Expands every instance whose record holds no statements from the
// libraries, taking its private variables from what its unit does not use
// and recording them (and the library and version) in the record, so that
// the saved file is self-contained. An instance that holds statements is
// left as it is: its statements are the program. When its block is known
// and they are no longer what the block makes of the record (edited by
// hand, or another version of the block), a warning at the record says so.
// Problems are at the records' lines and columns.
struct InstanceExpansion {
    lang::Diagnostics diagnostics;
    int expanded = 0; // instances whose statements were written in
};
InstanceExpansion expandInstances(lang::Document& document, const LibrarySet& libraries);
// The same with the libraries asked for when the first instance is found: a
// program without any reads none.
InstanceExpansion expandInstances(lang::Document& document,
                                  const std::function<const LibrarySet&()>& libraries);

// Reads project text (project::readProject) and, when it reads without
// errors, expands its instances; every diagnostic in the order of its place.
// The expanded statements stand at their record's line: lines and columns
// are those of the text as read.
struct ProjectWithInstances {
    project::ProjectReadResult read;
    bool expanded = false; // the project is no longer the text: it holds expansions
    std::vector<LibraryFileProblem> libraryProblems; // of the libraries it was read with
};
ProjectWithInstances readProjectWithInstances(std::string_view text, const LibrarySet& libraries);

// Where a project's libraries are looked for: the program's folder (for the
// standard ones), the project's file, and the user libraries given besides.
struct LibraryPlaces {
    QString executableDir;
    QString projectPath; // empty for a project without a file
    QStringList userFiles;
};

// The libraries the project uses (Project::libraries; every library found
// when it names none), with those of `places.userFiles`. A library the
// project names that is not found is a warning at the project's first line.
LibrarySet librariesFor(const LibraryPlaces& places,
                        const std::vector<std::string>& projectLibraries);

// Whether an entry of Project::libraries names a user library's file (else
// a standard library's name).
bool isUserLibraryEntry(std::string_view entry);

// The library an entry of Project::libraries stands for in a set made by
// librariesFor; nothing when it was not found.
const LoadedLibrary* libraryOfEntry(const LibrarySet& set, const LibraryPlaces& places,
                                    const std::string& entry);

// Reads the project, then expands its instances from the libraries it uses.
// The standard libraries are read only when the project names its libraries
// or has an instance (they were a third of a small project's check); the
// user's (`places.userFiles`, the project's folder) always are, so that their
// problems are reported.
ProjectWithInstances readProjectWithInstances(std::string_view text, const LibraryPlaces& places);

// Compiles a project read with its instances: the reading's diagnostics
// first, then the compiler's, by place. The compiler makes the images from
// the canonical text, expansions included, so the file as `format` writes it
// compiles to the same image.
compiler::CompileResult compileProject(const project::Project& project,
                                       const lang::Diagnostics& readDiagnostics,
                                       const compiler::CheckOptions& options = {},
                                       std::string_view readFrom = {},
                                       compiler::Output output = compiler::Output::Images);

} // namespace rs::blocks
