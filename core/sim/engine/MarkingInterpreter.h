// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "UnitState.h"
#include "sim/Conduction.h"

namespace rs::sim::engine {

// Runs step `index` instruction by instruction, marking what each one did in
// `marks` (the unit's conduction, indexed like its code): what a replay for
// conduction and eager conduction run. Kept apart from the fast interpreter,
// whose loop a mark per instruction would slow down (docs/simulator.md, "Speed").
void runMarking(UnitState& unit, int index, int& pendingJump, int cycleMs, Conduction* marks);

} // namespace rs::sim::engine
