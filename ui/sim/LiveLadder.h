// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "LivePower.h"
#include "ladder/LadderLiveState.h"

#include <set>
#include <vector>

namespace rs::sim {
class Simulation;
class UnitEngine;
} // namespace rs::sim

namespace rs::ui {

// Keeps a page's live state of station `station` up to date scan after
// scan, from what the engine reported (conduction, timers, memory), never
// from evaluating the logic again: power (render::LivePower), box values,
// forces, active steps. It touches only the statements whose conduction
// changed and the boxes whose values did: a page of thousands of networks
// costs little when little changes.
class LiveLadderBuilder {
public:
    // `watched`: the variables whose values the page shows (block pins).
    void update(LadderLiveState& state, const sim::Simulation& simulation, int station,
                const std::set<lang::Address>& watched = {});
    // The next update builds everything afresh (a new simulation began).
    void reset();

private:
    struct Box {
        std::pair<std::uint32_t, std::uint16_t> key;
        std::vector<std::size_t> instructions; // the box's timer or operands, in code order
        std::vector<std::int64_t> values;      // what the text shows now
    };
    void rebuild(LadderLiveState& state, const sim::UnitEngine& unit);
    // Reads the box's values again; whether any changed.
    bool readValues(const sim::UnitEngine& unit, Box& box) const;
    QString textOf(const sim::UnitEngine& unit, const Box& box) const;

    const sim::UnitEngine* m_unit = nullptr;
    std::size_t m_instructions = 0; // in the code the boxes were found in
    std::vector<Box> m_boxes;
    render::LivePower m_power;
};

} // namespace rs::ui
