// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"

#include <optional>
#include <string>
#include <string_view>

// What the New Project dialog and the project page edit (manual Part 1,
// 3.2 and 3.3): the name downloaded to the units, a description for the
// user's notes, and whether the compiled file carries the source code.
namespace rs::project {

// Why a name cannot be the project's "$name" (empty, several lines, a ';'
// that would start a comment), or nothing.
std::optional<std::string> checkProjectName(std::string_view name);

// A project with no units yet: "$name NAME" and its record.
Project newProject(std::string_view name, std::string description, bool includeSource);

// Writes the name into the "$name" line, adding the line when there is none.
std::optional<std::string> setProjectName(Project& project, std::string_view name);

} // namespace rs::project
