// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ScanMachineCode.h"
#include "UnitState.h"

#include <memory>

namespace rs::sim::engine {

// Each step of `unit` as machine code without marks, run with a FastContext
// (FastInterpreter.h); null where the machine or the system allows none, and
// the caller interprets (docs/simulator.md, "Speed"). The code points into
// `unit`, which must stay where it is.
std::unique_ptr<ScanMachineCode> lowerToMachineCode(UnitState& unit);

} // namespace rs::sim::engine
