// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ProjectDiff.h"
#include "compiler/Compiler.h"
#include "project/Project.h"

#include <string>

// The validated baseline (project/Baseline.h): marking a version as
// validated, and what changed since.
namespace rs::review {

// The project as it is now, compiled without errors, as a baseline: its
// signatures and the fingerprint of every network.
project::Baseline validatedBaseline(const project::Project& project,
                                    const compiler::CompileResult& compiled, std::string date,
                                    std::string by, std::string comment);

// What changed since the project's baseline, which it must have: units added
// or removed, networks added, removed or changed (matched by their
// fingerprints as `diff` matches them), and the signatures' verdict. The
// baseline keeps no text, so changes of names, descriptions and comments do
// not show.
ProjectDiff changesSinceValidation(const project::Project& project,
                                   const compiler::CompileResult& compiled);

} // namespace rs::review
