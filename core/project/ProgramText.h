// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"

#include <string>

namespace rs::project {

// The project as the manuals write a program file: the language alone,
// without the IDE's ";@" records, for a plain text editor or the original
// compiler. Descriptions, network grouping and attributes are left out.
std::string programText(const Project& project);

} // namespace rs::project
