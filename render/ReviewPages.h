// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Review.h"
#include "blocks/ProjectInstances.h"
#include "compiler/Compiler.h"
#include "project/Project.h"
#include "review/ProjectDiff.h"

#include <QString>

namespace rs::render {

// One side of a comparison: a project as read with its block instances, and
// what compiling it gave.
struct ReviewedVersion {
    QString path; // as the reviewer named it
    const project::Project& project;
    blocks::LibraryPlaces places; // where its libraries were found
    const compiler::CompileResult& compiled;
};

// The review of `diff` as pages to print and sign: the projects, their
// signatures, the date and what compared them, every line of the diff, then
// each network old beside new.
Review reviewPages(const ReviewedVersion& before, const ReviewedVersion& after,
                   const review::ProjectDiff& diff, const QString& comparedBy);

} // namespace rs::render
