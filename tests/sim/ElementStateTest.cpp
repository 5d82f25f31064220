// SPDX-License-Identifier: GPL-3.0-or-later
#include "SimulationFixture.h"

#include <gtest/gtest.h>

using rs::test::Simulated;
using rs::test::unitZero;

namespace {

// The state the last scan reported for element `element` of statement
// `statement` of unit 0: that of its last instruction, as for conduction.
std::uint8_t stateOf(const Simulated& s, std::uint32_t statement, std::uint16_t element) {
    const rs::sim::UnitEngine& unit = *s.simulation->unit(0);
    const auto& code = unit.image().code;
    const auto& states = unit.elementStates();
    std::uint8_t state = 0;
    bool found = false;
    for (std::size_t i = 0; i < code.size(); ++i)
        if (code[i].statement == statement && code[i].element == element) {
            state = states[i];
            found = true;
        }
    EXPECT_TRUE(found) << statement << "/" << element;
    return state;
}

bool closed(const Simulated& s, std::uint32_t statement, std::uint16_t element) {
    return (stateOf(s, statement, element) & rs::sim::ElementState::Closed) != 0;
}

bool running(const Simulated& s, std::uint32_t statement, std::uint16_t element) {
    return (stateOf(s, statement, element) & rs::sim::ElementState::Running) != 0;
}

// Element 1 is the series, 2 and 3 its contacts.
TEST(ElementState, AContactShowsItsBitWhetherOrNotPowerReachesIt) {
    Simulated s(unitZero("Q0.1 = I0.0 * I0.1\nQ0.2 = I0.0 * /I0.2\n"));
    s.set("I0.1", 1);
    s.scans(1);
    EXPECT_FALSE(closed(s, 0, 2));
    EXPECT_TRUE(closed(s, 0, 3)) << "I0.1 is 1 though I0.0 before it is open";
    EXPECT_TRUE(closed(s, 1, 3)) << "NC with its bit 0";
    s.set("I0.2", 1);
    s.set("I0.0", 1);
    s.scans(1);
    EXPECT_TRUE(closed(s, 0, 2));
    EXPECT_FALSE(closed(s, 1, 3)) << "NC with its bit 1, power at its left";
}

TEST(ElementState, AComparisonIsTrueOrFalseOnItsOwn) {
    Simulated s(unitZero("M0.0 = I0.0 * (R0.1 > 4) * /(R0.2 = 3)\n"));
    s.set("R0.1", 7);
    s.set("R0.2", 3);
    s.scans(1);
    EXPECT_TRUE(closed(s, 0, 3)) << "7 > 4 with no power arriving";
    EXPECT_TRUE(closed(s, 0, 4)) << "the comparison holds; the negation is the box's bubble";
    s.set("R0.1", 2);
    s.scans(1);
    EXPECT_FALSE(closed(s, 0, 3));
}

TEST(ElementState, ATimerSaysWhetherItCountsAndWhetherItsOutputIsOn) {
    Simulated s(unitZero("M0.0 = I0.0 * TON(0s05)\n"));
    s.scans(2);
    EXPECT_FALSE(running(s, 0, 3));
    EXPECT_FALSE(closed(s, 0, 3));
    s.set("I0.0", 1);
    s.scans(2);
    EXPECT_TRUE(running(s, 0, 3));
    EXPECT_FALSE(closed(s, 0, 3));
    s.scans(20);
    EXPECT_FALSE(running(s, 0, 3));
    EXPECT_TRUE(closed(s, 0, 3)) << "elapsed";
}

TEST(ElementState, AnEdgeIsClosedInTheScanThatSeesIt) {
    Simulated s(unitZero("M0.0 = I0.1 * P(I0.0)\n"));
    s.scans(1);
    s.set("I0.0", 1);
    s.scans(1);
    EXPECT_TRUE(closed(s, 0, 3)) << "I0.1 is open, the edge is seen all the same";
    s.scans(1);
    EXPECT_FALSE(closed(s, 0, 3));
}

TEST(ElementState, ABitOutputShowsItsVariableAfterTheScan) {
    // Q0.2's own rung is off; M0.1 is set by a latch that comes after it.
    Simulated s(unitZero("Q0.2 = I0.0\nM0.1 = I0.0\nS(M0.1) = I0.1\n"));
    s.set("I0.1", 1);
    s.simulation->force(Simulated::at("Q0.2"), 1);
    s.scans(1);
    EXPECT_TRUE(closed(s, 0, 0)) << "forced to 1 with its rung off";
    EXPECT_TRUE(closed(s, 1, 0)) << "set by a latch later in the scan";
    EXPECT_EQ(s.simulation->unit(0)->conduction()[2], rs::sim::Conduction::Off)
        << "the rung itself is off";
    s.simulation->release(Simulated::at("Q0.2"));
    s.set("I0.1", 0);
    s.scans(1);
    EXPECT_FALSE(closed(s, 0, 0));
    EXPECT_FALSE(closed(s, 1, 0)) << "its own rung wrote 0 and nothing set it again";
}

} // namespace
