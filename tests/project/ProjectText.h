// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "project/Project.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

// Reads project text that must be free of errors.
rs::project::Project projectFrom(std::string_view text);

// Writing the project and reading it back gives the same project, and writing
// that again the same bytes: what every edit must leave behind.
::testing::AssertionResult isStable(const rs::project::Project& project);

// The canonical text of a project.
std::string textOf(const rs::project::Project& project);
