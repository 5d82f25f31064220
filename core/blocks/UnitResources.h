// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "project/Project.h"

// How much of a unit's timers, memories and registers are taken, and how
// much of that by its block instances, against the unit's limits (50 timers;
// memories and registers by type, manual Part 1, 10). An instance's private
// variables count as taken even while no statement of it uses them: no
// other instance gets them.
namespace rs::blocks {

struct ResourceUse {
    int used = 0;     // all of the unit's, those of its instances included
    int byBlocks = 0; // timers in the instances' statements; their private variables
    int limit = 0;

    friend bool operator==(const ResourceUse&, const ResourceUse&) = default;
};

struct UnitResources {
    ResourceUse timers;
    ResourceUse memories;
    ResourceUse registers; // register words: a double register takes two

    friend bool operator==(const UnitResources&, const UnitResources&) = default;
};

UnitResources unitResources(const project::Project& project, int station);

} // namespace rs::blocks
