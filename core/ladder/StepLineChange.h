// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "UnitLadder.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace rs::ladder {

// Networks [first, first + removed) of a step's page replaced by `added`
// others (only those that differ), and how far the numbers of the
// statements after them moved.
struct NetworkRunChange {
    std::size_t first = 0;
    std::size_t removed = 0;
    std::size_t added = 0;
    std::int64_t statementShift = 0;
};

// Brings the ladder of a step up to date after a run of its lines changed:
// lines [first, first + removed.size()) of the step as `page` shows it are
// lines [first, first + added) of `step` now. Only the networks the run
// touches are read again (toLadder), so an edit costs its networks, not the
// step; the page ends as toLadder of the whole step would make it.
//
// Nothing, and the page unchanged, when block instances are concerned: a
// network drawn as a box, or a ";@block" or ";@end" record among the lines
// removed or added (which instances the step holds, and whether each is a
// box, only the whole unit tells). The caller makes sure that the step holds
// no instance drawn as statements either.
std::optional<NetworkRunChange> followLineChange(StepPage& page, const lang::Step& step,
                                                 std::size_t first,
                                                 std::span<const lang::Line> removed,
                                                 std::size_t added);

} // namespace rs::ladder
