// SPDX-License-Identifier: GPL-3.0-or-later
#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "sim/ScenarioRunner.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

const char* kReadingProgram = "! id_pluto:00=000000000000\n"
                              "! type_pluto:00=A20,is3\n"
                              "! I0.12=EStop\n"
                              "! pgm_pluto:00\n"
                              "! I0.12,a_pulse\n"
                              "S0.0_0\n"
                              "Q0.2 = EStop\n";

// The scenario's diagnostics as the CLI prints them, for a scenario that is not run.
std::vector<std::string> diagnostics(std::string_view scenarioText) {
    const auto read = project::readProject(kReadingProgram);
    const sim::Scenario scenario =
        sim::parseScenario(scenarioText, sim::OperandNames(read.project));
    std::vector<std::string> lines;
    for (const auto& diagnostic : scenario.diagnostics)
        lines.push_back(lang::formatDiagnostic("t.scn", diagnostic));
    return lines;
}

sim::ScenarioReport runReadScenario(std::string_view scenarioText) {
    const auto read = project::readProject(kReadingProgram);
    const auto compiled = compiler::compileText(kReadingProgram);
    EXPECT_EQ(compiled.errors(), 0);
    const sim::Scenario scenario =
        sim::parseScenario(scenarioText, sim::OperandNames(read.project));
    sim::Simulation simulation(compiled.images);
    return sim::runScenario("t.scn", scenario, simulation);
}

using Lines = std::vector<std::string>;

} // namespace

TEST(ScenarioReading, CycleOutsideOneMillisecondToTenSecondsIsRefusedAtItsValue) {
    const std::string refused = "error: the scan cycle must be 1ms to 10s";
    EXPECT_EQ(diagnostics("cycle 0ms\nexpect Q0.2 0\n"), Lines{"t.scn:1:7: " + refused});
    EXPECT_EQ(diagnostics("cycle 10s01\nexpect Q0.2 0\n"), Lines{"t.scn:1:7: " + refused});
    // Would wrap to a negative int in the simulation.
    EXPECT_EQ(diagnostics("cycle 999999999min\nexpect Q0.2 0\n"), Lines{"t.scn:1:7: " + refused});
    EXPECT_EQ(diagnostics("cycle -5ms\nexpect Q0.2 0\n"),
              Lines{"t.scn:1:7: error: expected a duration such as 10ms, 2.5s, 2s50 or 1min, "
                    "found '-5ms'"});
    EXPECT_TRUE(diagnostics("cycle 1ms\nexpect Q0.2 0\n").empty());
    EXPECT_TRUE(diagnostics("cycle 10s\nexpect Q0.2 0\n").empty());
}

TEST(ScenarioReading, VirtualTimePastThirtyDaysIsRefusedAtTheValue) {
    const std::string refused =
        "error: a scenario runs at most 30 days of virtual time; this line would pass that";
    EXPECT_TRUE(diagnostics("run 43200min\nexpect Q0.2 0\n").empty());
    EXPECT_EQ(diagnostics("run 43201min\nexpect Q0.2 0\n"), Lines{"t.scn:1:5: " + refused});
    EXPECT_EQ(diagnostics("run 999999999min\nexpect Q0.2 0\n"), Lines{"t.scn:1:5: " + refused});
    EXPECT_EQ(diagnostics("expect Q0.2 1 within 43201min\n"), Lines{"t.scn:1:22: " + refused});
    // scans at the default cycle of 10 ms, and at a cycle of 1 ms.
    EXPECT_TRUE(diagnostics("scans 259200000\nexpect Q0.2 0\n").empty());
    EXPECT_EQ(diagnostics("scans 259200001\nexpect Q0.2 0\n"), Lines{"t.scn:1:7: " + refused});
    EXPECT_EQ(diagnostics("cycle 1ms\nscans 2592000001\nexpect Q0.2 0\n"),
              Lines{"t.scn:2:7: " + refused});
    EXPECT_EQ(diagnostics("scans 99999999999999999999999\nexpect Q0.2 0\n"),
              Lines{"t.scn:1:7: " + refused});
    // The sum counts: each line alone is within the bound.
    EXPECT_EQ(diagnostics("run 43000min\nscans 100\nrun 200min\nexpect Q0.2 1 within 201min\n"),
              (Lines{"t.scn:3:5: " + refused, "t.scn:4:22: " + refused}));
}

TEST(ScenarioReading, ValuesOutOfTheOperandsRangeAreRefusedAtTheValue) {
    EXPECT_EQ(diagnostics("set R0.10 99999999999\nexpect Q0.2 0\n"),
              Lines{"t.scn:1:11: error: R0.10 is a register: its value is -32768..32767"});
    EXPECT_EQ(diagnostics("set R0.10 32768\nexpect R0.10 -32769\n"),
              (Lines{"t.scn:1:11: error: R0.10 is a register: its value is -32768..32767",
                     "t.scn:2:14: error: R0.10 is a register: its value is -32768..32767"}));
    EXPECT_EQ(diagnostics("set R0.10 99999999999999999999999\nexpect Q0.2 0\n"),
              Lines{"t.scn:1:11: error: R0.10 is a register: its value is -32768..32767"});
    EXPECT_EQ(diagnostics("set DR0.4 2147483648\nexpect Q0.2 0\n"),
              Lines{"t.scn:1:11: error: DR0.4 is a 32-bit value: its value is "
                    "-2147483648..2147483647"});
    EXPECT_EQ(diagnostics("expect R0.5.3 2\n"),
              Lines{"t.scn:1:15: error: R0.5.3 is a bit: its value is 0 or 1"});
    EXPECT_TRUE(diagnostics("set R0.10 -32768\nset R0.11 32767\nset DR0.4 -2147483648\n"
                            "set DR0.6 2147483647\nexpect R0.10 -32768\n")
                    .empty());
}

TEST(ScenarioReading, AByteOrderMarkIsSkipped) {
    EXPECT_TRUE(diagnostics("\xEF\xBB\xBFset EStop 1\nexpect Q0.2 0\n").empty());
    // Columns count characters after the mark.
    EXPECT_EQ(diagnostics("\xEF\xBB\xBFset Nothing 1\nexpect Q0.2 0\n"),
              Lines{"t.scn:1:5: error: unknown operand 'Nothing': use an address or a declared "
                    "name"});
}

TEST(ScenarioReading, ALoneCarriageReturnEndsALine) {
    EXPECT_EQ(diagnostics("set EStop 1\rwait 5s\r\nrun 10ms\rexpect Q0.2 1\r"),
              Lines{"t.scn:2:1: error: unknown line 'wait'; expected set, release, run, scans, "
                    "expect, cycle, disconnect or connect"});
    const sim::ScenarioReport report =
        runReadScenario("set EStop 1\rrun 10ms\rexpect Q0.2 1\rexpect Q0.2 1\r");
    EXPECT_EQ(report.passed, 2);
    EXPECT_EQ(report.failed, 0);
}

TEST(ScenarioReading, AScenarioThatExpectsNothingFailsOnce) {
    const Lines nothing{"t.scn:1:1: error: no expectation: a scenario must check something"};
    for (const char* text : {"", "\r", "\r\r\r", "; only a comment\n\n", "set EStop 1\nrun 1s\n"})
        EXPECT_EQ(diagnostics(text), nothing) << text;
    const sim::ScenarioReport report = runReadScenario("\r\r");
    EXPECT_EQ(report.passed, 0);
    EXPECT_EQ(report.failed, 1);
    EXPECT_EQ(report.diagnostics, nothing);
}

TEST(ScenarioReading, NulBytesAndBadUtf8AreRefusedWhereTheyAre) {
    using namespace std::string_literals;
    EXPECT_EQ(diagnostics("set EStop\0 1\nexpect Q0.2 0\n"s),
              Lines{"t.scn:1:10: error: NUL byte: not text"});
    EXPECT_EQ(diagnostics("expect Q0.2 0\nset \xC3\xA9\xFF 1\n"),
              Lines{"t.scn:2:6: error: invalid UTF-8: the file must be UTF-8 text"});
    // In a comment it does no harm.
    EXPECT_TRUE(diagnostics("expect Q0.2 0 ; \xFF\n").empty());
}
