// SPDX-License-Identifier: GPL-3.0-or-later
// The shipped Rungsmith_Speed library (docs/block-libraries.md):
// HS_SpeedCount_Up, HS_SpeedCount_Dir and SpeedMon1 written as body-less
// ;@block records are expanded, compiled and simulated, and do what the
// manual (Part 1, 9) and the library's definitions say. Scans are 10 ms.
#include "DiagnosticsText.h"
#include "blocks/LibraryReader.h"
#include "blocks/ProjectInstances.h"
#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "sim/ScenarioRunner.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using namespace rs;
using rs::test::diagnosticsText;

namespace {

blocks::LibrarySet speedLibrary() {
    std::ifstream file(RUNGSMITH_LIBRARIES "/Rungsmith_Speed.rslib", std::ios::binary);
    std::stringstream text;
    text << file.rdbuf();
    const auto read = blocks::readLibrary(text.str());
    EXPECT_TRUE(read.ok()) << (read.diagnostics.empty() ? "" : read.diagnostics[0].message);
    blocks::LibrarySet set;
    set.libraries.push_back(
        {read.library, QStringLiteral("Rungsmith_Speed.rslib"), blocks::LibraryOrigin::Standard});
    return set;
}

// A D45 counting up on IA0.0, up and down on IA0.2 and IA0.3, with a 4-20 mA
// input on IA0.1; `code` is its PLC code.
std::string speedD45(const std::string& code, const std::string& type = "D45,is3") {
    return "! id_pluto_Double:00=000000000000\n"
           "! type_pluto:00=" +
           type +
           "\n"
           "! pgm_pluto:00\n"
           "! IA0.0,counter_up\n"
           "! IA0.1,current\n"
           "! IA0.2,counter_updown\n"
           "! IA0.3,counter_updown\n"
           "! R0.1=Speed\n"
           "! R0.2=CompSpeed\n"
           "S0.0_0\n" +
           code;
}

// The project read with its instances expanded, compiled, and `scenario` run on it.
sim::ScenarioReport runSpeed(const std::string& text, const std::string& scenario) {
    const auto read = blocks::readProjectWithInstances(text, speedLibrary());
    EXPECT_TRUE(read.read.ok()) << diagnosticsText(read.read.diagnostics);
    const compiler::CompileResult compiled =
        blocks::compileProject(read.read.project, read.read.diagnostics);
    EXPECT_EQ(compiled.errors(), 0) << diagnosticsText(compiled.diagnostics);
    sim::Simulation simulation(compiled.images);
    return sim::runScenario(
        "t.scn", sim::parseScenario(scenario, sim::OperandNames(read.read.project)), simulation);
}

std::string failures(const sim::ScenarioReport& report) {
    std::string text;
    for (const auto& failure : report.failures)
        text += failure + "\n";
    return text;
}

// SpeedMon1 on Speed and CompSpeed, its outputs on M0.10 (SpeedValid), R0.3
// (ValidSpeed), M0.11 (StandStill), M0.12 (SafeLowSpeed).
std::string speedMon(const std::string& maxDiff, const std::string& diffDelay,
                     const std::string& lowSpeedLim = "150") {
    return ";@block SpeedMon1 Speed=\"Speed\" CompSpeed=\"CompSpeed\" MaxDiff=\"" + maxDiff +
           "\" DiffDelay=\"" + diffDelay + "\" LowSpeedLim=\"" + lowSpeedLim +
           "\" SpeedValid=\"M0.10\" ValidSpeed=\"R0.3\" StandStill=\"M0.11\" "
           "SafeLowSpeed=\"M0.12\"\n"
           ";@end\n";
}

} // namespace

TEST(Rungsmith_Speed, HS_SpeedCount_UpGivesPulsesASecondAndEdgesPer10ms) {
    const sim::ScenarioReport report = runSpeed(
        speedD45(";@block HS_SpeedCount_Up Input=\"IA0.0\" Valid=\"M0.1\" EdgePer10ms=\"R0.5\" "
                 "PulsePerSec=\"R0.6\"\n;@end\n"),
        "set IA0.0 488\nscans 1\nexpect M0.1 1\nexpect R0.5 5\nexpect R0.6 488\n"
        "set IA0.0 449\nscans 1\nexpect R0.5 4\n"
        "set IA0.0 14000\nscans 1\nexpect M0.1 1\nexpect R0.5 140\n"
        "set IA0.0 14001\nscans 1\nexpect M0.1 0\nexpect R0.6 14001\n"
        "set IA0.0 -1\nscans 1\nexpect M0.1 0\n"
        "set IA0.0 0\nscans 1\nexpect M0.1 1\nexpect R0.5 0\nexpect R0.6 0\n");
    EXPECT_EQ(failures(report), "");
    EXPECT_EQ(report.passed, 12);
}

TEST(Rungsmith_Speed, HS_SpeedCount_DirGivesTheDirectionAsTheSign) {
    const sim::ScenarioReport report = runSpeed(
        speedD45(";@block HS_SpeedCount_Dir Input_A=\"IA0.2\" Input_B=\"IA0.3\" Valid=\"M0.1\" "
                 "EdgePer10ms=\"R0.5\" PulsePerSec=\"R0.6\"\n;@end\n"),
        "set IA0.2 -450\nscans 1\nexpect M0.1 1\nexpect R0.5 -5\nexpect R0.6 -450\n"
        "set IA0.2 450\nscans 1\nexpect R0.5 5\nexpect R0.6 450\n"
        "set IA0.2 -14000\nscans 1\nexpect M0.1 1\n"
        "set IA0.2 -14001\nscans 1\nexpect M0.1 0\n");
    EXPECT_EQ(failures(report), "");
    EXPECT_EQ(report.passed, 7);
}

TEST(Rungsmith_Speed, ACounterInstanceIsSavedAsItsCall) {
    const std::string text =
        speedD45(";@block HS_SpeedCount_Up Input=\"IA0.0\" Valid=\"M0.1\" PulsePerSec=\"Speed\"\n"
                 ";@end\n");
    const auto result = blocks::readProjectWithInstances(text, speedLibrary());
    ASSERT_TRUE(result.read.ok()) << diagnosticsText(result.read.diagnostics);
    const std::string saved = project::writeProject(result.read.project);
    EXPECT_NE(saved.find(";@block HS_SpeedCount_Up Input=\"IA0.0\" Valid=\"M0.1\" "
                         "PulsePerSec=\"Speed\" lib=\"Rungsmith_Speed\" version=\"1.0\" "
                         "#pin.EdgePer10ms=\"R0.149\"\n"
                         ";@system HS_SpeedCount_Up Input=\"IA0.0\" Valid=\"M0.1\" "
                         "EdgePer10ms=\"R0.149\" PulsePerSec=\"Speed\"\n"
                         ";@end\n"),
              std::string::npos)
        << saved;
}

// |Speed - CompSpeed| <= MaxDiff, both ways, ends included.
TEST(Rungsmith_Speed, SpeedMon1IsValidWithinMaxDiffEitherWay) {
    const sim::ScenarioReport report =
        runSpeed(speedD45(speedMon("20", "R0.4")),
                 "set R0.4 0\n"
                 "set Speed 500\nset CompSpeed 480\nscans 1\nexpect M0.10 1\nexpect R0.3 500\n"
                 "set CompSpeed 520\nscans 1\nexpect M0.10 1\n"
                 "set CompSpeed 479\nscans 1\nexpect M0.10 0\nexpect R0.3 32767\n"
                 "set CompSpeed 521\nscans 1\nexpect M0.10 0\n"
                 "set CompSpeed 500\nscans 1\nexpect M0.10 1\nexpect R0.3 500\n"
                 "set Speed -500\nset CompSpeed -520\nscans 1\nexpect M0.10 1\nexpect R0.3 -500\n"
                 "set CompSpeed -521\nscans 1\nexpect M0.10 0\n");
    EXPECT_EQ(failures(report), "");
    EXPECT_EQ(report.passed, 11);
}

// DiffDelay holds SpeedValid on for its time after the comparison fails,
// counted as TON counts it: off in the scan after the time has passed.
TEST(Rungsmith_Speed, SpeedMon1sDiffDelayIsAnOffDelayOfTheComparison) {
    const sim::ScenarioReport report =
        runSpeed(speedD45(speedMon("R0.5", "0s20")),
                 "set R0.5 20\nset Speed 100\nset CompSpeed 100\nscans 5\n"
                 "set CompSpeed 121\nscans 20\nexpect M0.10 1\nexpect R0.3 100\n"
                 "scans 1\nexpect M0.10 0\nexpect R0.3 32767\n"
                 // A shorter excursion leaves no trace, and the delay starts afresh.
                 "set CompSpeed 100\nscans 1\nexpect M0.10 1\n"
                 "set CompSpeed 79\nscans 19\nset CompSpeed 100\nscans 1\n"
                 "set CompSpeed 79\nscans 20\nexpect M0.10 1\n"
                 // MaxDiff is read every scan.
                 "set R0.5 21\nscans 100\nexpect M0.10 1\n");
    EXPECT_EQ(failures(report), "");
    EXPECT_EQ(report.passed, 7);
}

// The comparison is exact over the whole register range: a bound that
// saturates never lets a larger difference pass, and no MaxDiff below 0
// is ever met.
TEST(Rungsmith_Speed, SpeedMon1ComparesExactlyAtTheEndsOfTheRange) {
    const sim::ScenarioReport report =
        runSpeed(speedD45(speedMon("R0.5", "R0.4")),
                 "set R0.4 0\n"
                 "set R0.5 100\nset Speed 32767\nset CompSpeed 32767\nscans 1\nexpect M0.10 1\n"
                 "set Speed -32768\nset CompSpeed -32768\nscans 1\nexpect M0.10 1\n"
                 "set R0.5 32767\nset Speed 32767\nset CompSpeed -32768\nscans 1\nexpect M0.10 0\n"
                 "set CompSpeed 0\nscans 1\nexpect M0.10 1\n"
                 "set R0.5 -1\nset Speed 0\nscans 1\nexpect M0.10 0\n"
                 "set R0.5 -32768\nscans 1\nexpect M0.10 0\n");
    EXPECT_EQ(failures(report), "");
    EXPECT_EQ(report.passed, 6);
}

// SafeLowSpeed is Speed < LowSpeedLim while the speed is valid: the limit is
// not safely low, and nothing is at a fault.
TEST(Rungsmith_Speed, SpeedMon1sSafeLowSpeedIsBelowTheLimitAndNeverAtAFault) {
    const sim::ScenarioReport report =
        runSpeed(speedD45(speedMon("20", "R0.4", "R0.6")),
                 "set R0.4 0\nset R0.6 150\n"
                 "set Speed 149\nset CompSpeed 149\nscans 1\nexpect M0.12 1\n"
                 "set Speed 150\nset CompSpeed 150\nscans 1\nexpect M0.12 0\n"
                 "set R0.6 151\nscans 1\nexpect M0.12 1\n"
                 "set Speed 0\nset CompSpeed 100\nscans 1\nexpect M0.10 0\nexpect M0.12 0\n"
                 // The limit compares the signed value, as the manual says.
                 "set Speed -500\nset CompSpeed -500\nscans 1\nexpect M0.12 1\n");
    EXPECT_EQ(failures(report), "");
    EXPECT_EQ(report.passed, 6);
}

// StandStill: Speed 0 with SpeedValid for 0.7 s (on in the 71st scan), then
// three scans with Speed not 0 are tolerated, in either direction, and the
// fourth ends it; a fault ends it at once.
TEST(Rungsmith_Speed, SpeedMon1sStandStillToleratesThreeMovesAfter700ms) {
    const sim::ScenarioReport report =
        runSpeed(speedD45(speedMon("20", "0s10")),
                 "scans 70\nexpect M0.11 0\nscans 1\nexpect M0.11 1\n"
                 "set Speed 5\nset CompSpeed 5\nscans 1\nset Speed -3\nscans 1\n"
                 "set Speed 0\nset CompSpeed 0\nscans 50\nset Speed 1\nscans 1\n"
                 "set Speed 0\nscans 1\nexpect M0.11 1\n"
                 "set Speed -1\nscans 1\nexpect M0.11 0\n"
                 "set Speed 0\nscans 70\nexpect M0.11 0\nscans 1\nexpect M0.11 1\n"
                 // Moving at a steady speed is moving: the fourth scan ends it.
                 "set Speed 1\nscans 3\nexpect M0.11 1\nscans 1\nexpect M0.11 0\n"
                 "set Speed 0\nscans 71\nexpect M0.11 1\n"
                 // CompSpeed only needs to be within MaxDiff...
                 "set CompSpeed 20\nscans 20\nexpect M0.11 1\n"
                 // ... and a fault ends the stand still when SpeedValid goes off.
                 "set CompSpeed 21\nscans 10\nexpect M0.11 1\nscans 1\nexpect M0.10 0\n"
                 "expect M0.11 0\n"
                 "set CompSpeed 0\nscans 70\nexpect M0.11 0\nscans 1\nexpect M0.11 1\n");
    EXPECT_EQ(failures(report), "");
    EXPECT_EQ(report.passed, 15);
}

TEST(Rungsmith_Speed, TwoSpeedMon1InstancesAreIndependent) {
    const sim::ScenarioReport report = runSpeed(
        speedD45(speedMon("20", "0s10") +
                 ";@block SpeedMon1 Speed=\"R0.20\" CompSpeed=\"R0.21\" MaxDiff=\"5\" "
                 "DiffDelay=\"0s10\" LowSpeedLim=\"10\" SpeedValid=\"M0.20\" StandStill=\"M0.21\" "
                 "SafeLowSpeed=\"M0.22\"\n;@end\n"),
        "set R0.20 7\nscans 71\nexpect M0.11 1\nexpect M0.21 0\nexpect M0.20 0\n"
        "expect M0.10 1\nexpect M0.12 1\nexpect M0.22 0\n"
        "set R0.21 7\nscans 1\nexpect M0.20 1\nexpect M0.22 1\n");
    EXPECT_EQ(failures(report), "");
    EXPECT_EQ(report.passed, 8);
}

// The body is ordinary statements of both instruction sets.
TEST(Rungsmith_Speed, SpeedMon1RunsOnInstructionSet2) {
    const sim::ScenarioReport report = runSpeed(
        "! id_pluto:00=000000000000\n! pgm_pluto:00\nS0.0_0\n" +
            std::string(";@block SpeedMon1 Speed=\"R0.1\" CompSpeed=\"R0.2\" MaxDiff=\"20\" "
                        "DiffDelay=\"0s10\" LowSpeedLim=\"150\" SpeedValid=\"Q0.0\" "
                        "StandStill=\"Q0.1\"\n;@end\n"),
        "set R0.1 100\nset R0.2 121\nscans 10\nexpect Q0.0 1\nscans 1\nexpect Q0.0 0\n"
        "set R0.1 0\nset R0.2 0\nscans 71\nexpect Q0.0 1\nexpect Q0.1 1\n");
    EXPECT_EQ(failures(report), "");
    EXPECT_EQ(report.passed, 4);
}

TEST(Rungsmith_Speed, AWrongInstanceIsAnErrorAtItsRecord) {
    struct Case {
        std::string record;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {";@block SpeedMon1 Speed=\"Speed\" CompSpeed=\"CompSpeed\" DiffDelay=\"0s50\" "
         "LowSpeedLim=\"150\"",
         "11:1: SpeedMon1: input MaxDiff is not bound and has no default\n"},
        {";@block SpeedMon1 Speed=\"100\" CompSpeed=\"CompSpeed\" MaxDiff=\"20\" "
         "DiffDelay=\"0s50\" LowSpeedLim=\"150\"",
         "11:19: SpeedMon1: pin Speed takes register or system-register, not '100'\n"},
        {";@block HS_SpeedCount_Up Input=\"IA0.2\" Valid=\"M0.1\"",
         "11:27: HS_SpeedCount_Up reads IA0.2 as a counter_up input, but line 6 declares it a "
         "counter_updown input\n"},
        {";@block HS_SpeedCount_Dir Input_A=\"IA0.1\" Input_B=\"IA0.3\"",
         "11:28: HS_SpeedCount_Dir reads IA0.1 as a counter_updown input, but line 5 declares "
         "it a current input\n"},
    };
    for (const auto& c : cases) {
        const auto read =
            blocks::readProjectWithInstances(speedD45(c.record + "\n;@end\n"), speedLibrary());
        lang::Diagnostics all = read.read.diagnostics;
        if (read.read.ok()) {
            const compiler::CompileResult compiled =
                blocks::compileProject(read.read.project, read.read.diagnostics);
            all = compiled.diagnostics;
        }
        lang::Diagnostics errors;
        for (const auto& d : all)
            if (d.severity == lang::Severity::Error)
                errors.push_back(d);
        EXPECT_EQ(diagnosticsText(errors), c.expected) << c.record;
    }
}
