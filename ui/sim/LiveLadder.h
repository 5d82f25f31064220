#pragma once

#include "ladder/LadderLiveState.h"

#include <vector>

namespace rs::sim {
class Simulation;
class UnitEngine;
} // namespace rs::sim

namespace rs::ui {

// The ladder page's picture of one unit after the last scan, taken from what
// the engine reported (per-instruction conduction, timers, memory), never
// from evaluating the logic again.

// Per statement that ran, the elements with power at their right side and
// whether the output was driven: the last instruction of an element tells.
render::PowerSnapshot powerSnapshot(const sim::UnitEngine& unit);

// Keeps a page's live state of station `station` up to date scan after
// scan (power, box values, forces, active steps), touching only the
// statements whose conduction changed and the boxes whose values did: a
// page of thousands of networks costs little when little changes.
class LiveLadderBuilder {
public:
    void update(LadderLiveState& state, const sim::Simulation& simulation, int station);
    // The next update builds everything afresh (a new simulation began).
    void reset() { m_unit = nullptr; }

private:
    struct Box {
        std::pair<std::uint32_t, std::uint16_t> key;
        std::vector<std::size_t> instructions; // the box's timer or operands, in code order
        std::vector<std::int64_t> values;      // what the text shows now
    };
    struct Statement {
        std::uint32_t number = 0;
        std::size_t first = 0;
        std::size_t count = 0;
    };
    void rebuild(LadderLiveState& state, const sim::UnitEngine& unit);
    // Reads the box's values again; whether any changed.
    bool readValues(const sim::UnitEngine& unit, Box& box) const;
    QString textOf(const sim::UnitEngine& unit, const Box& box) const;

    const sim::UnitEngine* m_unit = nullptr;
    std::vector<std::uint8_t> m_conduction; // as of the last update
    std::vector<Statement> m_statements;
    std::vector<Box> m_boxes;
};

} // namespace rs::ui
