// SPDX-License-Identifier: GPL-3.0-or-later
#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "sim/ScenarioRunner.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

const char* kCancelProgram = "! id_pluto:00=000000000000\n"
                             "! pgm_pluto:00\n"
                             "S0.0_0\n"
                             "Q0.2 = I0.0\n";

struct CancelledRun {
    sim::ScenarioReport report;
    std::int64_t endMs = 0;
};

CancelledRun runCancellable(const std::string& text, const sim::CancelRequest& cancelled) {
    const auto compiled = compiler::compileText(kCancelProgram);
    EXPECT_EQ(compiled.errors(), 0);
    const sim::Scenario scenario =
        sim::parseScenario(text, sim::OperandNames(project::readProject(kCancelProgram).project));
    sim::Simulation simulation(compiled.images);
    CancelledRun result{sim::runScenario("t.scn", scenario, simulation, nullptr, {}, cancelled), 0};
    result.endMs = simulation.timeMs();
    return result;
}

} // namespace

TEST(ScenarioCancel, StopsAtTheScanItIsAskedAfterAndSaysSo) {
    int asked = 0;
    const CancelledRun cancelled =
        runCancellable("set I0.0 1\nrun 20000min\nexpect Q0.2 1\n", [&] { return ++asked == 5; });
    EXPECT_TRUE(cancelled.report.cancelled);
    EXPECT_EQ(cancelled.endMs, 50); // five scans of 10 ms
    EXPECT_EQ(cancelled.report.passed + cancelled.report.failed, 0);
}

TEST(ScenarioCancel, AnExpectationWaitingWhenCancelledCountsNeither) {
    int asked = 0;
    const CancelledRun cancelled =
        runCancellable("expect Q0.2 1 within 10s\n", [&] { return ++asked == 3; });
    EXPECT_TRUE(cancelled.report.cancelled);
    EXPECT_EQ(cancelled.report.passed + cancelled.report.failed, 0);
}

TEST(ScenarioCancel, ARunNeverCancelledGivesTheSameReport) {
    const std::string text = "set I0.0 1\nscans 3\nexpect Q0.2 1\nexpect Q0.2 0 within 50ms\n";
    const CancelledRun plain = runCancellable(text, {});
    const CancelledRun asked = runCancellable(text, [] { return false; });
    EXPECT_FALSE(asked.report.cancelled);
    EXPECT_EQ(asked.report.passed, plain.report.passed);
    EXPECT_EQ(asked.report.failures, plain.report.failures);
    EXPECT_EQ(asked.endMs, plain.endMs);
    EXPECT_EQ(plain.report.passed, 1);
    EXPECT_EQ(plain.report.failed, 1);
}

TEST(ScenarioLength, CountsRunsScansAtTheirCycleAndWaits) {
    const auto project = project::readProject(kCancelProgram).project;
    const sim::OperandNames names(project);
    const sim::Scenario plain = sim::parseScenario("run 1s\nscans 10\nexpect Q0.2 0\n", names);
    ASSERT_TRUE(plain.diagnostics.empty());
    EXPECT_EQ(sim::scenarioLengthMs(plain, 10), 1000 + 100);
    const sim::Scenario slow =
        sim::parseScenario("cycle 20ms\nrun 1s\nscans 10\nexpect Q0.2 0 within 2s\n", names);
    ASSERT_TRUE(slow.diagnostics.empty());
    EXPECT_EQ(sim::scenarioLengthMs(slow, 10), 1000 + 200 + 2000);
}
