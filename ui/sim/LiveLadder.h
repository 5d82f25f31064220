// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "LivePower.h"
#include "ladder/LadderLiveState.h"
#include "sim/UnitMemory.h"

#include <QString>

#include <map>
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
    // Where one value of a box is read: resolved once per rebuild to the
    // unit's memory, so an update reads it without looking the address up.
    struct Source {
        enum class Kind : std::uint8_t { Word, Bit, Step, Timer } kind = Kind::Word;
        sim::WordRef word; // Word; Timer: its preset's register (None: a constant preset)
        sim::BitRef bit;
        int sequence = 0;        // Step
        std::size_t slot = 0;    // Timer
        std::int64_t preset = 0; // Timer with a constant preset, in ms
    };
    struct Box {
        std::pair<std::uint32_t, std::uint16_t> key;
        std::vector<std::size_t> instructions; // the box's timer or operands, in code order
        std::vector<Source> sources;           // one per instruction
        std::vector<std::int64_t> values;      // what the text shows now
        // An operand box's text, "R0.5=" for each operand once, by its value's index.
        std::vector<std::pair<std::size_t, QString>> labels;
    };
    void rebuild(LadderLiveState& state, const sim::UnitEngine& unit);
    // Reads the box's values again; whether any changed.
    bool readValues(const sim::UnitEngine& unit, Box& box) const;
    static QString textOf(const Box& box);

    const sim::UnitEngine* m_unit = nullptr;
    std::size_t m_instructions = 0; // in the code the boxes were found in
    std::vector<Box> m_boxes;
    // The boxes each operand appears in, to mark the forced ones.
    std::map<lang::Address, std::vector<std::pair<std::uint32_t, std::uint16_t>>> m_boxesOf;
    render::LivePower m_power;
};

} // namespace rs::ui
