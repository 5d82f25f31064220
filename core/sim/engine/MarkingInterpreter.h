// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "UnitState.h"
#include "sim/Conduction.h"

namespace rs::sim::engine {

// Runs step `index` instruction by instruction, marking what each one did in
// `marks` (the unit's conduction, indexed like its code) and the state of its
// element on its own in `states` (ElementState bits, indexed alike; the
// step's bit outputs are left to the caller, which reads their variables
// after the scan): what a replay for conduction and eager conduction run. Kept apart from the fast
// interpreter, whose loop a mark per instruction would slow down (docs/simulator.md, "Speed").
void runMarking(UnitState& unit, int index, int& pendingJump, int cycleMs, Conduction* marks,
                std::uint8_t* states);

} // namespace rs::sim::engine
