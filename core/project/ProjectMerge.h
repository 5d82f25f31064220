// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"

#include <optional>
#include <string>
#include <vector>

// The manual's Merge Project (Part 1, 12.2): the units of another project
// added to this one. Every unit must keep its station and every symbolic name
// must be one project's only; a name both use may be allowed ("ignore
// conflicts"), and it then stays only in the units where it was defined.
namespace rs::project {

struct MergeResult {
    std::optional<Project> merged; // none when there are conflicts
    // "station 1 is in both projects", "the name 'Start' is in both projects
    // (I0.0 and I1.0)": one per conflict, stations first.
    std::vector<std::string> conflicts;
};

// `into` keeps its name, description, options and baseline; `other` gives
// its units with their declarations, names, descriptions, exported and
// remanent variables, and its libraries. With `ignoreNameConflicts` a name
// both use becomes local to the unit of each variable it names (dropped for a
// unit without code), and other units' uses of it are written as addresses.
// Stations in both are always a conflict.
MergeResult mergeProjects(const Project& into, const Project& other, bool ignoreNameConflicts);

} // namespace rs::project
