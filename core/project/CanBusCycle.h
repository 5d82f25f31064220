// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"

// The unit page's Advanced settings (manual Part 1, 5.2): the CAN bus cycle
// time, how often a unit sends its global variables to the other units. The
// manual leaves its values to the hardware manual; Rungsmith keeps either
// the unit's default or a time the user chose, and the simulator delays
// what the unit publishes by it.
namespace rs::project {

// Limits Rungsmith enforces, the manual giving none.
inline constexpr int kMinCanCycleMs = 1;
inline constexpr int kMaxCanCycleMs = 1000;

// The unit's CAN bus cycle time in ms; 0 for the default.
int canCycleOf(const Project& project, int station);
// Sets it; 0 goes back to the default. An error outside the limits.
std::optional<std::string> setCanCycle(Project& project, int station, int ms);

} // namespace rs::project
