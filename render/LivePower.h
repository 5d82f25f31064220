// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "PowerSnapshot.h"

#include <cstdint>
#include <vector>

namespace rs::sim {
class UnitEngine;
}

namespace rs::render {

// The power picture of a unit after its last scan, taken from the conduction
// the engine marked for each instruction (the last instruction of an element
// tells whether it has power at its right side), never from evaluating the
// logic again. The IDE's live ladder and the command line both draw it.
PowerSnapshot powerSnapshot(const sim::UnitEngine& unit);

// Keeps the power picture of one unit up to date scan after scan, reading
// again only the statements whose conduction or element states changed: a unit of thousands of
// statements costs little when little changes.
class LivePower {
public:
    // Brings `snapshot` up to the unit's last scan; builds it afresh when the
    // unit or the snapshot is not the one of the previous update. Between
    // updates, only this changes the snapshot's statements.
    void update(PowerSnapshot& snapshot, const sim::UnitEngine& unit);
    // The next update builds everything afresh (a new simulation began).
    void reset() {
        m_unit = nullptr;
        m_snapshot = nullptr;
    }

private:
    struct Statement {
        std::uint32_t number = 0;
        std::size_t first = 0; // its instructions in the code
        std::size_t count = 0;
        // Its entry in the snapshot while it has one (a map's entries stay
        // where they are): a search of thousands of entries per changed
        // statement was most of an update. None for system calls, whose
        // ranges share one entry.
        StatementPower* power = nullptr;
    };
    void rebuild(PowerSnapshot& snapshot, const sim::UnitEngine& unit);

    const sim::UnitEngine* m_unit = nullptr;
    const PowerSnapshot* m_snapshot = nullptr; // the one the entries are in
    std::vector<std::uint8_t> m_conduction;    // as of the last update
    std::vector<std::uint8_t> m_states;        // the elements' own states, likewise
    std::vector<Statement> m_statements;
};

} // namespace rs::render
