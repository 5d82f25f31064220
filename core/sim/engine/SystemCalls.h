// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "DecodedInstruction.h"

namespace rs::sim::engine {

struct UnitState;

// Runs the system instruction `call` (a System instruction of the unit's
// decoded code) on the Arguments that follow it; every tier calls this.
// What each one does is written down in docs/image-format.md, "System
// instructions".
void runSystemCall(UnitState& unit, const DecodedInstruction& call);

} // namespace rs::sim::engine
