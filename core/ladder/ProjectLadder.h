// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Layout.h"
#include "SymbolTable.h"
#include "UnitLadder.h"
#include "blocks/InstanceStanding.h"
#include "blocks/ProjectInstances.h"
#include "project/Project.h"

#include <map>
#include <optional>
#include <vector>

namespace rs::ladder {

// Every unit's ladder as the ladder page shows it (block instances as boxes
// while they are what their block makes), to lay out any network of it: the
// networks of a review, old beside new.
class ProjectLadder {
public:
    // The project as read with its block instances; its libraries are found from `places`.
    ProjectLadder(const project::Project& project, const blocks::LibraryPlaces& places);

    // The unit has code (a pgm_pluto section).
    bool hasCode(int station) const { return m_units.count(station) > 0; }
    // How many networks the step has; -1 when its unit has no such step.
    int networkCount(const lang::StepAddress& step) const;
    // The network `number` (from 1) of a step; nothing when there is none.
    std::optional<NetworkLayout> layout(const lang::StepAddress& step, int number) const;

private:
    const StepPage* page(const lang::StepAddress& step) const;

    struct Unit {
        std::vector<StepPage> pages;
        SymbolTable symbols;
        std::vector<blocks::InstanceStatus> statuses;
    };
    // The blocks the statuses point to.
    blocks::LibrarySet m_libraries;
    std::map<int, Unit> m_units;
};

} // namespace rs::ladder
