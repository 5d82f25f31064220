// SPDX-License-Identifier: GPL-3.0-or-later
#include "ladder/PowerPaths.h"
#include "StepText.h"
#include "compiler/Compiler.h"
#include "ladder/TextToLadder.h"
#include "sim/Simulation.h"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <string>

namespace {

using namespace rs;

// The condition of the rung of `Q0.1 = <condition>` as the ladder reads it.
ladder::Circuit circuitOf(const std::string& condition) {
    const lang::Step step = test::stepWithCode("Q0.1 = " + condition + "\n");
    const ladder::StepLadder ladder = ladder::toLadder(step);
    return *std::get<ladder::Rung>(ladder.networks.front().items.front()).condition;
}

// What statement 0 of unit 0 conducted in the last scan, by element.
struct Scanned {
    std::set<std::uint16_t> conducting;
    std::set<std::uint16_t> closed; // the engine's own state of each element
    bool energised = false;
};

Scanned scanned(const sim::UnitEngine& unit) {
    Scanned s;
    const auto& code = unit.image().code;
    for (std::size_t i = 0; i < code.size(); ++i) {
        if (code[i].statement != 0)
            continue;
        if (code[i].element == 0) {
            s.energised = unit.conduction()[i] == sim::Conduction::On;
            continue;
        }
        if (unit.conduction()[i] == sim::Conduction::On)
            s.conducting.insert(code[i].element);
        else
            s.conducting.erase(code[i].element);
        if (unit.elementStates()[i] & sim::ElementState::Closed)
            s.closed.insert(code[i].element);
        else
            s.closed.erase(code[i].element);
    }
    return s;
}

TEST(PowerPaths, NamesTheFirstOpenContactOfEveryPath) {
    // I0.12 * (I0.13 + M0.0) * (I0.14 * I0.2 + Q0.2), numbered 1: the series,
    // 2: I0.12, 3: the first group, 4: I0.13, 5: M0.0, 6: the second group,
    // 7: its series, 8: I0.14, 9: I0.2, 10: Q0.2.
    const ladder::Circuit c = circuitOf("I0.12 * (I0.13 + M0.0) * (I0.14 * I0.2 + Q0.2)");
    // I0.12 closed, everything else open.
    const auto only = [](std::set<std::uint16_t> on) {
        return [on](std::uint16_t e) {
            return on.count(e) > 0;
        };
    };
    ladder::PowerPaths off = ladder::powerPaths(c, only({2}));
    EXPECT_FALSE(off.conducting);
    EXPECT_EQ(off.blockers, (std::vector<std::uint16_t>{4, 5}));
    EXPECT_TRUE(off.holding.empty());

    // Through M0.0 and Q0.2 (the holding contact): on, held by that path.
    ladder::PowerPaths on = ladder::powerPaths(c, only({1, 2, 3, 5, 6, 10}));
    EXPECT_TRUE(on.conducting);
    EXPECT_EQ(on.holding, (std::vector<std::uint16_t>{2, 5, 10}));
    EXPECT_EQ(on.blockers, (std::vector<std::uint16_t>{4, 8})) << "the paths that do not conduct";

    EXPECT_TRUE(ladder::powerPaths(std::nullopt, only({})).conducting) << "no condition";
}

// A random series/parallel condition of NO and NC contacts on eight inputs.
class RandomRung {
public:
    explicit RandomRung(unsigned seed) : m_random(seed) {}

    std::string condition(int depth) {
        if (depth == 0 || chance(30))
            return contact();
        const int parts = uniform(2, 3);
        const bool parallel = chance(50);
        std::string text = "(";
        for (int i = 0; i < parts; ++i) {
            if (i)
                text += parallel ? " + " : " * ";
            text += condition(depth - 1);
        }
        return text + ")";
    }

    std::string contact() {
        return std::string(chance(30) ? "/" : "") + "I0." + std::to_string(uniform(0, 7));
    }

    int uniform(int low, int high) {
        return std::uniform_int_distribution<int>(low, high)(m_random);
    }
    bool chance(int percent) { return uniform(1, 100) <= percent; }

private:
    std::mt19937 m_random;
};

// Every path of a circuit, its elements left to right, by brute force.
std::vector<std::vector<std::uint16_t>> allPaths(const ladder::Circuit& c, std::uint16_t number) {
    if (c.isElement())
        return {{number}};
    std::vector<std::vector<std::uint16_t>> paths;
    std::uint16_t part = number + 1;
    if (c.kind == ladder::Circuit::Kind::Parallel) {
        for (const auto& p : c.parts) {
            for (auto& path : allPaths(p, part))
                paths.push_back(std::move(path));
            part = static_cast<std::uint16_t>(part + ladder::nodeCount(p));
        }
        return paths;
    }
    paths.push_back({});
    for (const auto& p : c.parts) {
        std::vector<std::vector<std::uint16_t>> longer;
        for (const auto& head : paths)
            for (const auto& tail : allPaths(p, part)) {
                longer.push_back(head);
                longer.back().insert(longer.back().end(), tail.begin(), tail.end());
            }
        paths = std::move(longer);
        part = static_cast<std::uint16_t>(part + ladder::nodeCount(p));
    }
    return paths;
}

// Whether each contact is closed, from the inputs alone: NO with its bit 1,
// NC with its bit 0.
std::map<std::uint16_t, bool> closedContacts(const ladder::Circuit& c, std::uint16_t number,
                                             const sim::Simulation& simulation) {
    std::map<std::uint16_t, bool> closed;
    if (c.isElement()) {
        const auto& contact = std::get<ladder::Contact>(c.element);
        const bool bit = simulation.value(contact.operand.address) != 0;
        closed[number] = contact.kind == ladder::ElementKind::NormallyClosed ? !bit : bit;
        return closed;
    }
    std::uint16_t part = number + 1;
    for (const auto& p : c.parts) {
        closed.merge(closedContacts(p, part, simulation));
        part = static_cast<std::uint16_t>(part + ladder::nodeCount(p));
    }
    return closed;
}

// The why-off answer, from the engine's conduction, against brute force on
// the inputs: the first open contact of every path that has one, and a
// holding path all closed exactly when the output is driven.
TEST(PowerPaths, AgreesWithEveryPathEvaluatedByBruteForce) {
    RandomRung random(20261202);
    int tried = 0;
    int on = 0;
    for (int rung = 0; rung < 150; ++rung) {
        const std::string condition = random.condition(3);
        const auto compiled = compiler::compileText(
            "! id_pluto:00=000000000000\n! type_pluto:00=A20,is3\n! pgm_pluto:00\nS0.0_0\n"
            "Q0.1 = " +
            condition + "\n");
        ASSERT_EQ(compiled.errors(), 0) << condition;
        const ladder::Circuit circuit = circuitOf(condition);
        sim::Simulation simulation(compiled.images);
        const auto paths = allPaths(circuit, 1);
        for (int inputs = 0; inputs < 6; ++inputs) {
            for (int i = 0; i < 8; ++i)
                simulation.set(lang::Address{lang::AddressKind::Input, 0, i}, random.chance(55));
            simulation.scan();
            const Scanned s = scanned(*simulation.unit(0));
            const auto closed = closedContacts(circuit, 1, simulation);
            std::set<std::uint16_t> expected;
            bool anyClosedPath = false;
            for (const auto& path : paths) {
                const auto open = std::find_if(path.begin(), path.end(),
                                               [&](std::uint16_t e) { return !closed.at(e); });
                if (open == path.end())
                    anyClosedPath = true;
                else
                    expected.insert(*open);
            }
            for (const auto& [element, isClosed] : closed)
                ASSERT_EQ(s.closed.count(element) > 0, isClosed)
                    << condition << " element " << element << ": the engine's own state";

            const ladder::PowerPaths answer = ladder::powerPaths(
                circuit, [&](std::uint16_t e) { return s.conducting.count(e) > 0; });
            const std::string where = condition + " inputs " + std::to_string(inputs);
            EXPECT_EQ(std::set<std::uint16_t>(answer.blockers.begin(), answer.blockers.end()),
                      expected)
                << where;
            EXPECT_EQ(answer.conducting, s.energised) << where;
            EXPECT_EQ(anyClosedPath, s.energised) << where;
            if (s.energised) {
                ++on;
                EXPECT_NE(std::find(paths.begin(), paths.end(), answer.holding), paths.end())
                    << where << ": a path of the rung";
                for (std::uint16_t e : answer.holding)
                    EXPECT_TRUE(closed.at(e)) << where << ": holding through a closed contact";
            } else {
                EXPECT_TRUE(answer.holding.empty()) << where;
            }
            ++tried;
        }
    }
    EXPECT_EQ(tried, 900);
    EXPECT_GT(on, 100) << "both answers come up";
    EXPECT_LT(on, 800);
}

} // namespace
