// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Diagnostic.h"
#include "lang/ElementNumbering.h"

#include <map>
#include <string>

namespace rs::project {
struct Project;
}

namespace rs::ladder {

// The messages of a unit's diagnostics by the element the ladder draws them
// on. The diagnostics carry lines and columns of the unit's text as its text
// page shows it (project::unitText); a message on a line without a statement
// has no element. Several messages on one element are joined by line breaks.
std::map<lang::ElementNumber, std::string> problemsByElement(const project::Project& project,
                                                             int station,
                                                             const lang::Diagnostics& diagnostics);

} // namespace rs::ladder
