// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <random>
#include <string>

namespace rs::test {

// Random programs that compile: two units on one bus, each with PLC code and
// a sequence, using every kind of instruction the engine runs (contacts on
// inputs, memories, register bits and the other unit's globals; edges; the
// three timers with constant and register presets; comparisons; latches and
// toggles; saturating arithmetic and division; jumps and sequence resets).
class RandomScanProgram {
public:
    explicit RandomScanProgram(unsigned seed) : m_random(seed) {}
    std::string text();

private:
    int uniform(int low, int high) {
        return std::uniform_int_distribution<int>(low, high)(m_random);
    }
    bool chance(int percent) { return uniform(1, 100) <= percent; }
    std::string bit(bool forWriting);
    std::string reg() { return "R" + std::to_string(m_unit) + "." + std::to_string(uniform(0, 5)); }
    std::string leaf();
    std::string term(int depth);
    std::string expression(int depth);
    std::string statement(bool inSequence, int steps);

    std::mt19937 m_random;
    int m_unit = 0;
};

} // namespace rs::test
