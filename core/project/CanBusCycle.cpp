// SPDX-License-Identifier: GPL-3.0-or-later
#include "CanBusCycle.h"

namespace rs::project {

int canCycleOf(const Project& project, int station) {
    auto it = project.canCycleMs.find(station);
    return it == project.canCycleMs.end() ? 0 : it->second;
}

std::optional<std::string> setCanCycle(Project& project, int station, int ms) {
    if (ms != 0 && (ms < kMinCanCycleMs || ms > kMaxCanCycleMs))
        return "the CAN bus cycle time must be " + std::to_string(kMinCanCycleMs) + "-" +
               std::to_string(kMaxCanCycleMs) + " ms";
    if (ms == 0)
        project.canCycleMs.erase(station);
    else
        project.canCycleMs[station] = ms;
    return std::nullopt;
}

} // namespace rs::project
