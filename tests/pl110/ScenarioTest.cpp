// SPDX-License-Identifier: GPL-3.0-or-later
#include "pl110/Scenario.h"
#include "pl110/ProgramCheck.h"
#include "pl110/ProgramText.h"
#include "project/ProjectFile.h"

#include <gtest/gtest.h>

namespace rs::pl110 {
namespace {

Program program(std::string_view text) {
    ProgramReading reading = readProgram(text);
    EXPECT_TRUE(reading.diagnostics.empty());
    EXPECT_TRUE(checkProgram(reading.program).empty());
    return reading.program;
}

const char* const kLatch = "$target PL110\n! I1=Start\n! I2=Stop\n! Q1=Motor\n! VW3=Speed\n"
                           "MAIN\nMotor = Start * /Stop + Motor * /Stop\n(Speed = 5) = Motor\n";

std::string run(std::string_view scenarioText) {
    const Program latch = program(kLatch);
    const ScenarioNames names(latch);
    const Scenario scenario = parseScenario(scenarioText, names);
    ScanEngine engine(latch);
    const sim::ScenarioReport report = runScenario("s.scn", scenario, engine);
    std::string text;
    for (const auto& line : report.diagnostics)
        text += line + "\n";
    for (const auto& line : report.failures)
        text += line + "\n";
    return text + std::to_string(report.passed) + " passed, " + std::to_string(report.failed) +
           " failed";
}

TEST(Pl110Scenario, RunsWithNamesAndAddressesOnVirtualTime) {
    EXPECT_EQ(run("set start 1\nscans 1\nset Start 0\nexpect Motor 1\nexpect VW3 5\n"
                  "run 1s\nexpect Q1 1\nset I2 1\nexpect Motor 0 within 20ms\n"),
              "4 passed, 0 failed");
    EXPECT_EQ(run("set Start 1\nexpect Motor 1 within 30ms\nexpect Speed 6\n"),
              "s.scn:3: expect Speed 6 failed: got 5 at t=0.010s\n1 passed, 1 failed");
}

TEST(Pl110Scenario, ASetOfAnOutputHoldsItAgainstTheProgramUntilReleased) {
    // Stop is pressed: the program wants the motor off.
    EXPECT_EQ(
        run("set Stop 1\nset Motor 1\nscans 5\nexpect Motor 1\nexpect Speed 5\nrelease Motor\n"
            "scans 1\nexpect Motor 0\nset Speed 9\nset Stop 0\nset Start 1\nscans 2\n"
            "expect Motor 1\nexpect Speed 9\n"),
        "5 passed, 0 failed");
}

TEST(Pl110Scenario, SaysWhatIsWrongAtItsLineAndColumn) {
    EXPECT_EQ(run("set Nothing 1\nset Start 2\nset VW3 40000\nexpect I0 1\nconnect 0\n"),
              "s.scn:1:5: error: unknown operand 'Nothing': use an address or a declared name\n"
              "s.scn:2:11: error: I1 is a bit: its value is 0 or 1\n"
              "s.scn:3:9: error: VW3 is a word: its value is -32768..32767\n"
              "s.scn:4:8: error: I0 is out of range: I1-I256\n"
              "s.scn:5:9: error: expected the number of one of the project's units, found '0'\n"
              "0 passed, 1 failed");
}

TEST(Pl110Scenario, TheExampleProjectPassesItsScenarios) {
    for (const char* name : {"filling-station.scn", "filling-station-overrun.scn"}) {
        const project::FileText projectText =
            project::readTextFile(RUNGSMITH_EXAMPLES "/pl110/filling-station.sps");
        const project::FileText scenarioText =
            project::readTextFile(QString(RUNGSMITH_EXAMPLES "/pl110/") + name);
        ASSERT_TRUE(projectText.error.isEmpty() && scenarioText.error.isEmpty());
        const Program station = program(projectText.text);
        ScanEngine engine(station);
        const sim::ScenarioReport report =
            runScenario(name, parseScenario(scenarioText.text, ScenarioNames(station)), engine);
        EXPECT_EQ(report.failed, 0) << name;
        EXPECT_GT(report.passed, 5) << name;
    }
}

} // namespace
} // namespace rs::pl110
