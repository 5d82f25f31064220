// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "PowerSnapshot.h"

#include <cstdint>
#include <vector>

namespace rs::render {

// The power picture of a scan from an engine that reports each statement's
// marks itself (statement n is byStatement[n - 1]): whether it ran, whether
// its output was energised, each element's power and state by element number.
template <class Marks> PowerSnapshot snapshotOfMarks(const std::vector<Marks>& byStatement) {
    PowerSnapshot snapshot;
    for (std::size_t index = 0; index < byStatement.size(); ++index) {
        const Marks& marks = byStatement[index];
        if (!marks.ran)
            continue;
        StatementPower& power = snapshot.statements[static_cast<std::uint32_t>(index + 1)];
        power.energised = marks.energised;
        power.states = marks.states;
        for (std::size_t element = 1; element < marks.power.size(); ++element)
            if (marks.power[element])
                power.conducting.insert(static_cast<std::uint16_t>(element));
    }
    return snapshot;
}

} // namespace rs::render
