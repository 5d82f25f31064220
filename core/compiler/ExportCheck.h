// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "UnitSetup.h"
#include "lang/Diagnostic.h"
#include "project/Project.h"

namespace rs::compiler {

// Gives each unit the variables the project exports from it, and reports
// what the file says about exports that the original tool would have refused
// (a file edited by hand): a variable that cannot be exported, a unit over 4
// extra telegram pairs, a project over 16. Reported at the exporting unit's
// declaration, as the records have no line of their own in the program.
void collectExports(const project::Project& project, UnitSetups& units,
                    lang::Diagnostics& diagnostics);

} // namespace rs::compiler
