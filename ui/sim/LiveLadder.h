#pragma once

#include "ladder/LadderLiveState.h"

namespace rs::sim {
class Simulation;
class UnitEngine;
} // namespace rs::sim

namespace rs::ui {

// The ladder page's picture of one unit after the last scan, taken from what
// the engine reported (per-instruction conduction, timers, memory), never
// from evaluating the logic again.

// Per statement that ran, the elements with power at their right side and
// whether the output was driven: the last instruction of an element tells.
render::PowerSnapshot powerSnapshot(const sim::UnitEngine& unit);

// Text for boxes: a timer's elapsed and preset time, the registers a
// comparison or an arithmetic output reads and writes.
std::map<std::pair<std::uint32_t, std::uint16_t>, QString>
boxAnnotations(const sim::UnitEngine& unit);

// Everything the page shows of station `station`; an empty state when the
// simulation has no such unit.
void fillLiveState(LadderLiveState& state, const sim::Simulation& simulation, int station);

} // namespace rs::ui
