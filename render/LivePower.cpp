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
    m_snapshot = &snapshot;
    for (Statement& statement : m_statements) {
        const auto found = snapshot.statements.find(statement.number);
        statement.power =
            statement.number == compiler::kNoStatement || found == snapshot.statements.end()
                ? nullptr
                : &found->second;
    }
    const auto& conduction = unit.conduction();
    m_conduction.resize(conduction.size());
    std::memcpy(m_conduction.data(), conduction.data(), conduction.size());
    m_states = unit.elementStates();
}

void LivePower::update(PowerSnapshot& snapshot, const sim::UnitEngine& unit) {
    if (&unit != m_unit || &snapshot != m_snapshot ||
        m_conduction.size() != unit.conduction().size()) {
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
    // Differences come in the order of the code, so the statement they are in
    // is found walking on from the previous one.
    auto statement = m_statements.begin();
    while (true) {
        const std::size_t differs = std::min(marks, states);
        if (differs == size)
            break;
        while (std::next(statement) != m_statements.end() && std::next(statement)->first <= differs)
            ++statement;
        std::memcpy(before + statement->first, now + statement->first, statement->count);
        std::memcpy(beforeStates + statement->first, nowStates + statement->first,
                    statement->count);
        // A statement runs whole or not at all. One that ran is brought up to
        // date in place: every element's last instruction sets it again, and
        // nothing is allocated unless what conducts changed.
        if (now[statement->first] != static_cast<std::uint8_t>(sim::Conduction::NotRun)) {
            StatementPower* power = statement->power;
            if (!power) {
                power = &snapshot.statements[statement->number];
                if (statement->number != compiler::kNoStatement)
                    statement->power = power;
            }
            statementPower(unit, statement->first, statement->count, *power);
        } else {
            snapshot.statements.erase(statement->number);
            statement->power = nullptr;
        }
        const std::size_t at = statement->first + statement->count;
        if (marks < at)
            marks = nextDifference(before, now, at);
        if (states < at)
            states = nextDifference(beforeStates, nowStates, at);
    }
}

} // namespace rs::render
