// SPDX-License-Identifier: GPL-3.0-or-later
#include "LivePower.h"

#include "sim/UnitEngine.h"

#include <algorithm>
#include <cstring>

namespace rs::render {

namespace {

// Adds what the instructions [first, first + count) of one statement did to
// its power; false when none of them ran.
bool statementPower(const sim::UnitEngine& unit, std::size_t first, std::size_t count,
                    StatementPower& power) {
    const auto& code = unit.image().code;
    const auto& conduction = unit.conduction();
    const auto& states = unit.elementStates();
    bool ran = false;
    for (std::size_t i = first; i < first + count; ++i) {
        if (conduction[i] == sim::Conduction::NotRun)
            continue;
        ran = true;
        const bool on = conduction[i] == sim::Conduction::On;
        const std::uint16_t element = code[i].element;
        // The last instruction of an element has its state (a comparison's
        // after its loads, an output's after the rung's start).
        if (element >= power.states.size())
            power.states.resize(element + 1u, 0);
        power.states[element] = states[i];
        if (element == 0)
            power.energised = on; // the rung's start and its output; the output comes last
        else if (on)
            power.conducting.insert(element);
        else
            power.conducting.erase(element);
    }
    return ran;
}

} // namespace

PowerSnapshot powerSnapshot(const sim::UnitEngine& unit) {
    PowerSnapshot snapshot;
    const auto& code = unit.image().code;
    for (std::size_t first = 0; first < code.size();) {
        std::size_t end = first + 1;
        while (end < code.size() && code[end].statement == code[first].statement)
            ++end;
        auto [power, added] = snapshot.statements.try_emplace(code[first].statement);
        if (!statementPower(unit, first, end - first, power->second) && added)
            snapshot.statements.erase(power);
        first = end;
    }
    return snapshot;
}

void LivePower::rebuild(PowerSnapshot& snapshot, const sim::UnitEngine& unit) {
    m_unit = &unit;
    const auto& code = unit.image().code;
    m_statements.clear();
    for (std::size_t i = 0; i < code.size(); ++i) {
        if (m_statements.empty() || m_statements.back().number != code[i].statement ||
            m_statements.back().first + m_statements.back().count != i)
            m_statements.push_back({code[i].statement, i, 0});
        ++m_statements.back().count;
    }
    snapshot = powerSnapshot(unit);
    const auto& conduction = unit.conduction();
    m_conduction.resize(conduction.size());
    std::memcpy(m_conduction.data(), conduction.data(), conduction.size());
    m_states = unit.elementStates();
}

void LivePower::update(PowerSnapshot& snapshot, const sim::UnitEngine& unit) {
    if (&unit != m_unit || m_conduction.size() != unit.conduction().size()) {
        rebuild(snapshot, unit);
        return;
    }
    const auto* now = reinterpret_cast<const std::uint8_t*>(unit.conduction().data());
    const std::uint8_t* nowStates = unit.elementStates().data();
    std::uint8_t* before = m_conduction.data();
    std::uint8_t* beforeStates = m_states.data();
    const std::size_t size = m_conduction.size();
    // Only where the marks or the states differ: usually a few statements of
    // thousands. Each array is searched once, from where its last difference was.
    const auto nextDifference = [size](const std::uint8_t* a, const std::uint8_t* b,
                                       std::size_t from) {
        return static_cast<std::size_t>(std::mismatch(a + from, a + size, b + from).first - a);
    };
    std::size_t marks = nextDifference(before, now, 0);
    std::size_t states = nextDifference(beforeStates, nowStates, 0);
    while (true) {
        const std::size_t differs = std::min(marks, states);
        if (differs == size)
            break;
        const auto statement = std::prev(std::upper_bound(
            m_statements.begin(), m_statements.end(), differs,
            [](std::size_t index, const Statement& s) { return index < s.first; }));
        std::memcpy(before + statement->first, now + statement->first, statement->count);
        std::memcpy(beforeStates + statement->first, nowStates + statement->first,
                    statement->count);
        StatementPower power;
        if (statementPower(unit, statement->first, statement->count, power))
            snapshot.statements[statement->number] = std::move(power);
        else
            snapshot.statements.erase(statement->number);
        const std::size_t at = statement->first + statement->count;
        if (marks < at)
            marks = nextDifference(before, now, at);
        if (states < at)
            states = nextDifference(beforeStates, nowStates, at);
    }
}

} // namespace rs::render
