// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "PowerSnapshot.h"

#include <QString>

#include <cstdint>
#include <map>
#include <set>
#include <utility>

namespace rs::ui {

// What the simulator says about one unit after its last scan, as the ladder page shows it.
// The page only draws this; it never evaluates logic.
struct LadderLiveState {
    render::PowerSnapshot power; // statements that ran and elements that conducted
    // Text shown on a box or under an element, by (statement number in unit, element number),
    // e.g. a timer's elapsed time "1.20 s / 3.00 s", a register's value "R3 = 17".
    std::map<std::pair<std::uint32_t, std::uint16_t>, QString> annotations;
    // Operand addresses that are forced, spelled as ladder::ElementLayout::address spells them
    // (e.g. "I0.2", "M1.5", "R3"); such elements are marked (e.g. a red "F" badge).
    std::set<QString> forced;
    // Boxes (by statement and element) with a forced operand besides their
    // address: a register compared with or computed from.
    std::set<std::pair<std::uint32_t, std::uint16_t>> forcedElements;
    // Active step per sequence (1..9) of the unit; a sequence page marks its active step.
    std::map<int, int> activeSteps;
};

} // namespace rs::ui
