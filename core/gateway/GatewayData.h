// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "sim/Simulation.h"
#include "target/UnitType.h"

#include <cstdint>

// The data a gateway takes from the Pluto bus (Gateway manual 4.1, 4.2), as
// 4-byte blocks read the way ../shared/spec/gateway.md says: the UDINT
// byte0 | byte1 << 8 | byte2 << 16 | byte3 << 24.
namespace rs::gateway {

// Node Status: bit k is Pluto k, present on the bus.
std::uint32_t nodeStatus(const sim::Simulation& simulation);

// A Pluto's global data in the layout of its family (A20 and Double
// families, AS-i, B42 AS-i), from its variables as the bus carries them.
std::uint32_t globalData(target::UnitType type, const sim::UnitMemory& published);
// The same for station `station` of the simulation; a station the project
// does not have is read in the A20 layout from what was set on its bus slot.
std::uint32_t globalData(const sim::Simulation& simulation, int station);

} // namespace rs::gateway
