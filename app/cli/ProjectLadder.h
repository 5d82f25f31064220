// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ProjectLoading.h"
#include "blocks/InstanceStanding.h"
#include "blocks/ProjectInstances.h"
#include "ladder/Layout.h"
#include "ladder/SymbolTable.h"
#include "ladder/UnitLadder.h"

#include <map>
#include <optional>
#include <vector>

namespace rs::cli {

// Every unit's ladder as the ladder page shows it (block instances as boxes
// while they are what their block makes), to lay out any network of it.
class ProjectLadder {
public:
    explicit ProjectLadder(const LoadedProject& loaded);

    // The network `number` (from 1) of a step; nothing when there is none.
    std::optional<ladder::NetworkLayout> layout(const lang::StepAddress& step, int number) const;

private:
    struct Unit {
        std::vector<ladder::StepPage> pages;
        ladder::SymbolTable symbols;
        std::vector<blocks::InstanceStatus> statuses;
    };
    // The blocks the statuses point to.
    blocks::LibrarySet m_libraries;
    std::map<int, Unit> m_units;
};

} // namespace rs::cli
