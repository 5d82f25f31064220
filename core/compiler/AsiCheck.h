// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "UnitSetup.h"
#include "project/Project.h"

namespace rs::compiler {

// Warns where the code and the AS-i Options page disagree (manual Part 1,
// 7.1.4: "the compiler will show warnings that the slaves are not
// configured"): an AS-i variable of a slave that is not defined, or that its
// slave's type does not have; AS-i variables of a unit whose bus is not used;
// a slave output written by a unit that only monitors the bus; AS-i options
// stored for a unit that is no AS-i unit. Once per slave and unit.
void checkAsiSlaves(const project::Project& project, const UnitSetups& units,
                    lang::Diagnostics& diagnostics);

} // namespace rs::compiler
