// SPDX-License-Identifier: GPL-3.0-or-later
#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "sim/ScenarioRunner.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

const char* kObserverProgram = "! id_pluto:00=000000000000\n"
                               "! pgm_pluto:00\n"
                               "! I0.0,a_pulse\n"
                               "S0.0_0\n"
                               "Q0.2 = I0.0 * TON(0s05)\n";

struct Compiled {
    project::Project project;
    std::vector<compiler::UnitImage> images;
};

Compiled compileProgram() {
    auto compiled = compiler::compileText(kObserverProgram);
    EXPECT_EQ(compiled.errors(), 0);
    return {project::readProject(kObserverProgram).project, compiled.images};
}

} // namespace

TEST(ScenarioObserver, SeesPowerOnAndEveryScanOfTheRun) {
    Compiled c = compileProgram();
    sim::OperandNames names(c.project);
    const sim::Scenario scenario =
        sim::parseScenario("set I0.0 1\nrun 30ms\nscans 2\nexpect Q0.2 1 within 100ms\n", names);
    sim::Simulation simulation(c.images);
    std::vector<std::pair<std::int64_t, std::int64_t>> seen; // time, Q0.2
    const lang::Address q02 = lang::readAddressWord("Q0.2").address;
    const sim::ScenarioReport report =
        sim::runScenario("t.scn", scenario, simulation, nullptr, [&](const sim::Simulation& s) {
            seen.emplace_back(s.timeMs(), s.value(q02));
        });
    EXPECT_EQ(report.passed, 1);
    // Power on, three scans of `run 30ms`, two of `scans 2`; Q0.2 is on from the scan at 50 ms.
    ASSERT_EQ(seen.size(), 7u);
    EXPECT_EQ(seen.front(), std::make_pair(std::int64_t{0}, std::int64_t{0}));
    EXPECT_EQ(seen[5], std::make_pair(std::int64_t{50}, std::int64_t{0}));
    EXPECT_EQ(seen.back(), std::make_pair(std::int64_t{60}, std::int64_t{1}));
}

TEST(ScenarioObserver, FailuresCarryTheirLines) {
    Compiled c = compileProgram();
    sim::OperandNames names(c.project);
    const sim::Scenario scenario =
        sim::parseScenario("expect Q0.2 1\n; a comment\nset I0.0 1\nrun 10ms\nexpect Q0.2 0\n"
                           "expect Q0.2 1\n",
                           names);
    sim::Simulation simulation(c.images);
    const sim::ScenarioReport report = sim::runScenario("t.scn", scenario, simulation);
    EXPECT_EQ(report.passed, 1);
    EXPECT_EQ(report.failureLines, (std::vector<int>{1, 6}));
    ASSERT_EQ(report.failures.size(), 2u);
}

TEST(ScenarioObserver, ValuesSampledElsewhereGiveTheSameTrace) {
    Compiled c = compileProgram();
    sim::OperandNames names(c.project);
    const sim::Scenario scenario =
        sim::parseScenario("set I0.0 1\nrun 80ms\nset I0.0 0\nscans 2\nexpect I0.0 0\n", names);
    const auto traced = sim::traceSignals(c.images, sim::touchedBy(scenario));
    sim::Simulation simulation(c.images);
    sim::VcdTrace direct(traced);
    sim::VcdTrace replayed(traced);
    sim::runScenario("t.scn", scenario, simulation, &direct, [&](const sim::Simulation& s) {
        std::vector<std::int64_t> values;
        for (const auto& signal : traced)
            values.push_back(s.value(signal));
        replayed.sample(s.timeMs(), values);
    });
    EXPECT_EQ(replayed.text("t"), direct.text("t"));
    EXPECT_NE(direct.text("t").find("#60\n1"), std::string::npos);
}
