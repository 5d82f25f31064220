// SPDX-License-Identifier: GPL-3.0-or-later
#include "LivePower.h"

#include "compiler/Compiler.h"
#include "sim/Simulation.h"

#include <gtest/gtest.h>

namespace {

using namespace rs;

lang::Address addressOf(const char* word) {
    return lang::readAddressWord(word).address;
}

// Statement 0 is a contact and a coil; sequence 1 has two steps, so a
// statement of the step that is not active does not run.
sim::Simulation twoSteps() {
    const auto compiled = compiler::compileText("! id_pluto:00=000000000000\n! pgm_pluto:00\n"
                                                "S0.0_0\nQ0.1 = I0.2*/I0.3\n"
                                                "S0.1_00\nQ0.2 = I0.4\nJ(+1) = I0.5\n"
                                                "S0.1_01\nQ0.3 = I0.4\n");
    EXPECT_EQ(compiled.errors(), 0);
    return sim::Simulation(compiled.images);
}

TEST(LivePower, TheSnapshotSaysWhatTheScanConducted) {
    sim::Simulation simulation = twoSteps();
    simulation.scan();
    render::PowerSnapshot before = render::powerSnapshot(*simulation.unit(0));
    EXPECT_TRUE(before.ran(0));
    // The series is element 1, its contacts I0.2 and /I0.3 elements 2 and 3.
    EXPECT_FALSE(before.conducts(0, 2)); // I0.2 is off
    EXPECT_FALSE(before.conducts(0, 0));

    simulation.set(addressOf("I0.2"), 1);
    simulation.scan();
    const render::PowerSnapshot after = render::powerSnapshot(*simulation.unit(0));
    EXPECT_TRUE(after.conducts(0, 2));
    EXPECT_TRUE(after.conducts(0, 3)); // /I0.3
    EXPECT_TRUE(after.conducts(0, 0)); // Q0.1 driven
}

TEST(LivePower, TheSnapshotSaysEachElementsOwnState) {
    sim::Simulation simulation = twoSteps();
    simulation.set(addressOf("I0.3"), 1);
    simulation.scan();
    render::PowerSnapshot snapshot = render::powerSnapshot(*simulation.unit(0));
    EXPECT_FALSE(snapshot.closed(0, 2)); // I0.2 is 0
    EXPECT_FALSE(snapshot.closed(0, 3)); // /I0.3 with I0.3 1: open
    simulation.set(addressOf("I0.3"), 0);
    simulation.scan();
    snapshot = render::powerSnapshot(*simulation.unit(0));
    EXPECT_TRUE(snapshot.closed(0, 3)) << "closed, though I0.2 before it lets no power through";
    EXPECT_FALSE(snapshot.conducts(0, 3));

    simulation.force(addressOf("Q0.1"), 1);
    simulation.scan();
    snapshot = render::powerSnapshot(*simulation.unit(0));
    EXPECT_TRUE(snapshot.closed(0, 0)) << "forced on";
    EXPECT_FALSE(snapshot.conducts(0, 0)) << "its rung is off";
    EXPECT_FALSE(snapshot.closed(3, 0)) << "a statement that did not run has no state";
}

TEST(LivePower, AStatementOfAStepThatIsNotActiveDidNotRun) {
    sim::Simulation simulation = twoSteps();
    simulation.scan();
    simulation.scan();
    const render::PowerSnapshot snapshot = render::powerSnapshot(*simulation.unit(0));
    EXPECT_TRUE(snapshot.ran(1));  // Q0.2 in step 0
    EXPECT_FALSE(snapshot.ran(3)); // Q0.3 in step 1
}

TEST(LivePower, KeptUpToDateEqualsOneTakenAfresh) {
    sim::Simulation simulation = twoSteps();
    render::LivePower live;
    render::PowerSnapshot kept;
    simulation.scan();
    live.update(kept, *simulation.unit(0));
    // I0.3 alone changes only the state of /I0.3: no power reaches it.
    for (const char* input : {"I0.3", "I0.3", "I0.2", "I0.4", "I0.3", "I0.5", "I0.2", "I0.4"}) {
        const lang::Address address = addressOf(input);
        simulation.set(address, 1 - simulation.value(address));
        simulation.scan();
        live.update(kept, *simulation.unit(0));
        const render::PowerSnapshot fresh = render::powerSnapshot(*simulation.unit(0));
        ASSERT_EQ(kept.statements.size(), fresh.statements.size()) << input;
        for (const auto& [statement, power] : fresh.statements) {
            ASSERT_TRUE(kept.ran(statement)) << input << " " << statement;
            EXPECT_EQ(kept.statements.at(statement).conducting, power.conducting) << input;
            EXPECT_EQ(kept.statements.at(statement).energised, power.energised) << input;
            EXPECT_EQ(kept.statements.at(statement).states, power.states) << input;
        }
    }
    EXPECT_EQ(simulation.unit(0)->activeStep(1), 1); // the run went through both steps
}

} // namespace
