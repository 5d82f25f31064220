// SPDX-License-Identifier: GPL-3.0-or-later
#include "DiagnosticsText.h"
#include "sim/LiveLadder.h"

#include "compiler/Compiler.h"
#include "sim/Simulation.h"

#include <gtest/gtest.h>

using namespace rs;
using rs::test::addressOf;

namespace {

// Statement 0 compares two registers; statement 1 adds one to another.
sim::Simulation registers() {
    const auto compiled =
        compiler::compileText("! id_pluto:00=000000000000\n! type_pluto:00=A20,is3\n"
                              "! pgm_pluto:00\nS0.0_0\nM0.0 = (R0.1 > R0.2)\n(R0.3 += R0.4)\n");
    EXPECT_EQ(compiled.errors(), 0);
    return sim::Simulation(compiled.images);
}

TEST(SimulationLiveLadder, BoxesShowTheirRegistersAndAForcedOneMarksTheBox) {
    sim::Simulation simulation = registers();
    simulation.force(addressOf("R0.2"), 7);
    simulation.force(addressOf("R0.1"), 9);
    simulation.scan();
    ui::LadderLiveState state;
    ui::LiveLadderBuilder builder;
    builder.update(state, simulation, 0);
    // The comparison is element 1 of statement 0; the arithmetic the output of statement 1.
    const auto comparison = std::make_pair(std::uint32_t{0}, std::uint16_t{1});
    ASSERT_TRUE(state.annotations.count(comparison));
    EXPECT_EQ(state.annotations.at(comparison), QStringLiteral("R0.1=9  R0.2=7"));
    EXPECT_TRUE(state.forcedElements.count(comparison));
    EXPECT_TRUE(state.forced.count(QStringLiteral("R0.2")));
    EXPECT_TRUE(state.power.conducts(0, 1)); // 9 > 7

    simulation.release(addressOf("R0.2"));
    simulation.scan();
    builder.update(state, simulation, 0);
    EXPECT_TRUE(state.forcedElements.count(comparison)); // R0.1 still is
    simulation.release(addressOf("R0.1"));
    simulation.scan();
    builder.update(state, simulation, 0);
    EXPECT_FALSE(state.forcedElements.count(comparison));
    EXPECT_TRUE(state.forced.empty());
}

TEST(SimulationLiveLadder, TheValuesOfTheVariablesOnBlockPinsAreTheEnginesAfterTheScan) {
    sim::Simulation simulation = registers();
    simulation.force(addressOf("R0.3"), 40);
    simulation.force(addressOf("R0.4"), 2);
    simulation.scan();
    ui::LadderLiveState state;
    ui::LiveLadderBuilder builder;
    builder.update(state, simulation, 0, {addressOf("R0.4"), addressOf("M0.0")});
    EXPECT_EQ(state.power.values, (std::map<lang::Address, std::int64_t>{{addressOf("R0.4"), 2},
                                                                         {addressOf("M0.0"), 0}}));
    simulation.force(addressOf("R0.4"), 5);
    simulation.scan();
    builder.update(state, simulation, 0, {addressOf("R0.4")});
    EXPECT_EQ(state.power.values, (std::map<lang::Address, std::int64_t>{{addressOf("R0.4"), 5}}))
        << "only what the page watches now";
}

} // namespace
