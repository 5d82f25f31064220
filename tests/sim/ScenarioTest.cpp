// SPDX-License-Identifier: GPL-3.0-or-later
#include "SimulationFixture.h"

#include "project/ProjectFile.h"
#include "sim/ScenarioRunner.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

const char* kScenarioProgram = "! id_pluto:00=000000000000\n"
                               "! type_pluto:00=A20,is3\n"
                               "! I0.12=EStop\n"
                               "! pgm_pluto:00\n"
                               "! I0.12,a_pulse\n"
                               "! I0.13,a_pulse\n"
                               "! M0.5=Running\n"
                               "S0.0_0\n"
                               "Q0.2 = EStop * I0.13\n"
                               "Running = Q0.2 * TON(0s50)\n"
                               "(R0.5 += 1) = P(I0.13)\n";

struct ScenarioRun {
    sim::ScenarioReport report;
    std::string vcd;
};

ScenarioRun runScenarioText(const std::string& scenarioText,
                            const char* program = kScenarioProgram) {
    auto read = project::readProject(program);
    auto compiled = compiler::compileText(program);
    EXPECT_EQ(compiled.errors(), 0);
    sim::OperandNames names(read.project);
    sim::Scenario scenario = sim::parseScenario(scenarioText, names);
    sim::Simulation simulation(compiled.images);
    sim::VcdTrace trace(sim::traceSignals(compiled.images, sim::touchedBy(scenario)));
    ScenarioRun result{sim::runScenario("t.scn", scenario, simulation, &trace), {}};
    result.vcd = trace.text("t.scn");
    return result;
}

} // namespace

TEST(Scenario, DurationsInEveryNotation) {
    std::int64_t ms = 0;
    EXPECT_TRUE(sim::parseDuration("10ms", ms));
    EXPECT_EQ(ms, 10);
    EXPECT_TRUE(sim::parseDuration("2.5s", ms));
    EXPECT_EQ(ms, 2500);
    EXPECT_TRUE(sim::parseDuration("2s50", ms));
    EXPECT_EQ(ms, 2500);
    EXPECT_TRUE(sim::parseDuration("2s5", ms));
    EXPECT_EQ(ms, 2500);
    EXPECT_TRUE(sim::parseDuration("1min", ms));
    EXPECT_EQ(ms, 60000);
    EXPECT_TRUE(sim::parseDuration("0.015s", ms));
    EXPECT_EQ(ms, 15);
    EXPECT_FALSE(sim::parseDuration("1.0005s", ms));
    EXPECT_FALSE(sim::parseDuration("ten", ms));
    EXPECT_FALSE(sim::parseDuration("5", ms));
    EXPECT_FALSE(sim::parseDuration("s5", ms));
}

TEST(Scenario, PassingExpectationsCountOnceEach) {
    ScenarioRun r = runScenarioText(
        "; both channels\nset EStop 1\nset I0.13 1   # and the beam\nrun 30ms\n"
        "expect Q0.2 1\nexpect Running 0\nexpect Running 1 within 1s\nexpect R0.5 0\n");
    EXPECT_EQ(r.report.passed, 4);
    EXPECT_EQ(r.report.failed, 0);
    EXPECT_TRUE(r.report.failures.empty());
}

TEST(Scenario, FailuresSayWhereWhatAndWhen) {
    // The value after the last scan counts: setting an input changes nothing until a scan.
    ScenarioRun r =
        runScenarioText("set EStop 1\nset I0.13 1\nrun 20ms\nexpect Q0.2 0\nset EStop 0\n"
                        "expect Q0.2 1\nrun 10ms\nexpect Q0.2 1 within 30ms\n");
    EXPECT_EQ(r.report.passed, 1);
    EXPECT_EQ(r.report.failed, 2);
    EXPECT_EQ(r.report.failures,
              (std::vector<std::string>{"t.scn:4: expect Q0.2 0 failed: got 1 at t=0.020s",
                                        "t.scn:8: expect Q0.2 1 within 30ms failed: still 0 at "
                                        "t=0.060s"}));
}

TEST(Scenario, WithinWaitsOnlyAsLongAsNeeded) {
    ScenarioRun r =
        runScenarioText("set EStop 1\nset I0.13 1\nexpect Q0.2 1 within 1s\nexpect R0.5 0\n");
    EXPECT_EQ(r.report.passed, 2);
}

TEST(Scenario, ForcingAndReleasingAnOutput) {
    ScenarioRun r = runScenarioText(
        "set Q0.2 1\nscans 2\nexpect Q0.2 1\nrelease Q0.2\nscans 1\nexpect Q0.2 0\n");
    EXPECT_EQ(r.report.passed, 2);
    EXPECT_EQ(r.report.failed, 0);
}

TEST(Scenario, SequenceStepsAndTheCycle) {
    const char* program = "! id_pluto:00=000000000000\n! pgm_pluto:00\nS0.0_0\nS0.1_0\n"
                          "J(+1) = TON(0s10)\nS0.1_1\n";
    ScenarioRun r = runScenarioText(
        "cycle 20ms\nexpect S0.1 0\nrun 100ms\nexpect S0.1 0\nrun 20ms\nexpect S0.1 1\n", program);
    EXPECT_EQ(r.report.passed, 3) << (r.report.failures.empty() ? "" : r.report.failures[0]);
}

TEST(Scenario, SyntaxErrorsAreReportedAndCountAsOneFailure) {
    ScenarioRun r =
        runScenarioText("set EStop 2\nrun 10 ms\nexpect Nothing 1\nwait 5s\nrun 10ms\ncycle 5ms\n"
                        "expect Q0.2 1 inside 5s\nset\n");
    EXPECT_EQ(r.report.failed, 1);
    EXPECT_EQ(r.report.passed, 0);
    EXPECT_EQ(
        r.report.diagnostics,
        (std::vector<std::string>{
            "t.scn:1:11: error: I0.12 is a bit: its value is 0 or 1",
            "t.scn:2:8: error: unexpected 'ms'; the form is run DURATION",
            "t.scn:3:8: error: unknown operand 'Nothing': use an address or a declared name",
            "t.scn:4:1: error: unknown line 'wait'; expected set, release, run, scans, expect, "
            "cycle, disconnect or connect",
            "t.scn:6:1: error: cycle must come before the first run",
            "t.scn:7:15: error: expected 'within', found 'inside'",
            "t.scn:8:1: error: missing argument; the form is set OPERAND VALUE",
        }));
}

TEST(Scenario, TraceIsStandardVcdAndTheSameEveryRun) {
    const char* scenario =
        "set EStop 1\nset I0.13 1\nrun 100ms\nset EStop 0\nrun 20ms\nexpect EStop 0\n";
    ScenarioRun first = runScenarioText(scenario);
    ScenarioRun second = runScenarioText(scenario);
    EXPECT_EQ(first.vcd, second.vcd);
    EXPECT_NE(first.vcd.find("$timescale 1ms $end"), std::string::npos);
    EXPECT_NE(first.vcd.find("$scope module pluto0 $end"), std::string::npos);
    EXPECT_NE(first.vcd.find("$var wire 1 ! I12 $end"), std::string::npos);
    EXPECT_NE(first.vcd.find("$var integer 32 % R5 $end"), std::string::npos);
    EXPECT_NE(first.vcd.find("$enddefinitions $end\n#0\n$dumpvars\n"), std::string::npos);
    // Signals sorted by address: I0.12 "!", I0.13 "\"", Q0.2 "#". Q0.2 comes on in the
    // first scan and drops in the scan after the stop.
    EXPECT_NE(first.vcd.find("#10\n1!\n1\"\n1#\n"), std::string::npos);
    EXPECT_NE(first.vcd.find("#110\n0!\n0#\n"), std::string::npos);
}

// Unit 1 reads unit 0's input and unit 0 reads unit 1's; a unit off the bus
// sees neither the other nor its variables, and neither is seen.
TEST(Scenario, AUnitOffTheBusSeesNoOtherAndIsSeenByNone) {
    const char* twoUnits = "! id_pluto:00=000000000000\n"
                           "! id_pluto:01=000000000001\n"
                           "! type_pluto:00=A20,is3\n"
                           "! type_pluto:01=A20,is3\n"
                           "! pgm_pluto:00\n"
                           "! I0.0,static\n"
                           "S0.0_0\n"
                           "Q0.2 = I1.0\n"
                           "! pgm_pluto:01\n"
                           "! I1.0,static\n"
                           "S1.0_0\n"
                           "Q1.2 = I0.0\n";
    ScenarioRun r =
        runScenarioText("set I0.0 1\nset I1.0 1\nscans 3\n"
                        "expect Q0.2 1\nexpect Q1.2 1\nexpect SM0.101 1\nexpect SM1.100 1\n"
                        "disconnect 1\nscans 2\n"
                        "expect Q0.2 0\nexpect Q1.2 0\nexpect SM0.101 0\nexpect SM1.100 0\n"
                        "expect SM1.101 1\n"
                        "connect 1\nscans 2\nexpect Q0.2 1\nexpect Q1.2 1\n",
                        twoUnits);
    EXPECT_EQ(r.report.failed, 0) << (r.report.failures.empty() ? "" : r.report.failures[0]);
    EXPECT_EQ(r.report.passed, 11);
    // A new run starts with every unit on the bus.
    ScenarioRun again = runScenarioText("disconnect 0\nscans 2\nexpect Q1.2 0\n", twoUnits);
    EXPECT_EQ(again.report.passed, 1);
    ScenarioRun unknown = runScenarioText("disconnect 7\nexpect Q0.2 0\n", twoUnits);
    ASSERT_EQ(unknown.report.diagnostics.size(), 1U);
    EXPECT_EQ(unknown.report.diagnostics[0],
              "t.scn:1:12: error: expected the number of one of the project's units, found '7'");
}

// An illuminated push button: `set` presses the button the program reads,
// whatever the program does with the lamp.
TEST(Scenario, SetsAnIqButtonNotItsLamp) {
    const char* program = "! id_pluto:00=000000000000\n"
                          "! type_pluto:00=A20,is3\n"
                          "! IQ0.14=Reset\n"
                          "! pgm_pluto:00\n"
                          "S0.0_0\n"
                          "Q0.2 = Reset\n"
                          "Q0.14 = /Q0.2\n";
    const auto result = runScenarioText("set Reset 1\nscans 1\nexpect Q0.2 1\nexpect Q0.14 0\n"
                                        "set IQ0.14 0\nscans 2\nexpect Q0.2 0\nexpect Q0.14 1\n",
                                        program);
    EXPECT_EQ(result.report.failed, 0) << result.report.failures.front();
    EXPECT_EQ(result.report.passed, 4);
}
