// SPDX-License-Identifier: GPL-3.0-or-later
// The shipped Analog01 library (docs/block-libraries.md): ReadVoltage,
// ReadCurrent and their _32 forms written as body-less ;@block records are
// expanded, compiled and simulated, and do what the manual (Part 1, 8) says.
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

blocks::LibrarySet analog01() {
    std::ifstream file(RUNGSMITH_LIBRARIES "/Analog01.rslib", std::ios::binary);
    std::stringstream text;
    text << file.rdbuf();
    const auto read = blocks::readLibrary(text.str());
    EXPECT_TRUE(read.ok()) << (read.diagnostics.empty() ? "" : read.diagnostics[0].message);
    blocks::LibrarySet set;
    set.libraries.push_back(
        {read.library, QStringLiteral("Analog01.rslib"), blocks::LibraryOrigin::Standard});
    return set;
}

// A D45 with a photocell's speed on IA0.0 and a frequency converter's 4-20 mA
// on IA0.1 (manual Part 1, 9.2), a 0-10 V input on IA0.2 and a 4-20 mA one on
// IA0.3; `code` is its PLC code.
std::string analog01D45(const std::string& code) {
    return "! id_pluto_Double:00=000000000000\n"
           "! type_pluto:00=D45,is3\n"
           "! pgm_pluto:00\n"
           "! IA0.1,current\n"
           "! IA0.2,voltage\n"
           "! IA0.3,current\n"
           "! R0.10=Speed_Freq_Conv\n"
           "S0.0_0\n" +
           code;
}

// The project read with its instances expanded, compiled, and `scenario` run on it.
sim::ScenarioReport runAnalog01(const std::string& text, const std::string& scenario) {
    const auto read = blocks::readProjectWithInstances(text, analog01());
    EXPECT_TRUE(read.read.ok()) << diagnosticsText(read.read.diagnostics);
    const compiler::CompileResult compiled =
        blocks::compileProject(read.read.project, read.read.diagnostics);
    EXPECT_EQ(compiled.errors(), 0) << diagnosticsText(compiled.diagnostics);
    sim::Simulation simulation(compiled.images);
    return sim::runScenario(
        "t.scn", sim::parseScenario(scenario, sim::OperandNames(read.read.project)), simulation);
}

std::string firstFailure(const sim::ScenarioReport& report) {
    return report.failures.empty() ? "" : report.failures.front();
}

const std::string kSpeed = ";@block ReadCurrent Input=\"IA0.1\" Value_4mA=\"0\" Value_20mA=\"488\" "
                           "Q=\"M0.1\" Scaled_Value=\"Speed_Freq_Conv\"\n"
                           ";@end\n";

} // namespace

TEST(Analog01, TheManualsFrequencyConverterReads488At20mAAndMinus122AtAWireBreak) {
    const sim::ScenarioReport report =
        runAnalog01(analog01D45(kSpeed), "set IA0.1 4000\n"
                                         "scans 1\n"
                                         "expect M0.1 1\n"
                                         "expect Speed_Freq_Conv 0\n"
                                         "set IA0.1 20000\n"
                                         "scans 1\n"
                                         "expect Speed_Freq_Conv 488\n"
                                         "set IA0.1 12000\n"
                                         "scans 1\n"
                                         "expect Speed_Freq_Conv 244\n"
                                         "set IA0.1 0\n"
                                         "scans 1\n"
                                         "expect M0.1 0\n"
                                         "expect Speed_Freq_Conv -122\n");
    EXPECT_EQ(report.failed, 0) << firstFailure(report);
    EXPECT_EQ(report.passed, 6);
}

TEST(Analog01, AnInstanceIsSavedAsItsCallAndReadsBackWithoutTheLibrary) {
    const auto result = blocks::readProjectWithInstances(analog01D45(kSpeed), analog01());
    ASSERT_TRUE(result.read.ok()) << diagnosticsText(result.read.diagnostics);
    const std::string text = project::writeProject(result.read.project);
    // The open Current takes a register of the instance's own.
    EXPECT_NE(text.find(";@block ReadCurrent Input=\"IA0.1\" Value_4mA=\"0\" Value_20mA=\"488\" "
                        "Q=\"M0.1\" Scaled_Value=\"Speed_Freq_Conv\" lib=\"Analog01\" "
                        "version=\"1.0\" #pin.Current=\"R0.149\"\n"
                        ";@system ReadCurrent Input=\"IA0.1\" Value_4mA=\"0\" "
                        "Value_20mA=\"488\" Q=\"M0.1\" Current=\"R0.149\" "
                        "Scaled_Value=\"Speed_Freq_Conv\"\n"
                        ";@end\n"),
              std::string::npos)
        << text;
    const compiler::CompileResult compiled =
        blocks::compileProject(result.read.project, result.read.diagnostics);
    ASSERT_EQ(compiled.errors(), 0) << diagnosticsText(compiled.diagnostics);
    EXPECT_EQ(compiler::compileText(text).images, compiled.images);
    const auto again = blocks::readProjectWithInstances(text, blocks::LibrarySet{});
    EXPECT_TRUE(again.read.diagnostics.empty()) << diagnosticsText(again.read.diagnostics);
    EXPECT_EQ(project::writeProject(again.read.project), text);
}

TEST(Analog01, ReadVoltageGivesMillivoltsAndTheScaleBetweenItsTwoValues) {
    const sim::ScenarioReport report = runAnalog01(
        analog01D45(";@block ReadVoltage Input=\"IA0.2\" Value_0V=\"R0.20\" Value_10V=\"1000\" "
                    "Q=\"M0.2\" Voltage=\"R0.21\" Scaled_Value=\"R0.22\"\n"
                    ";@end\n"),
        "set R0.20 -1000\n"
        "set IA0.2 7500\n"
        "scans 1\n"
        "expect M0.2 1\nexpect R0.21 7500\nexpect R0.22 500\n"
        "set IA0.2 10000\nscans 1\nexpect M0.2 1\nexpect R0.22 1000\n"
        "set IA0.2 0\nscans 1\nexpect M0.2 1\nexpect R0.22 -1000\n"
        // Out of range both ways: Q off, the line goes on.
        "set IA0.2 10001\nscans 1\nexpect M0.2 0\nexpect R0.22 1000\n"
        "set IA0.2 12000\nscans 1\nexpect M0.2 0\nexpect R0.22 1400\n"
        "set IA0.2 -1\nscans 1\nexpect M0.2 0\nexpect R0.22 -1000\n"
        "set IA0.2 -500\nscans 1\nexpect M0.2 0\nexpect R0.21 -500\nexpect R0.22 -1100\n"
        // From 0 to 1000, 1 mV is 0.1: to the nearest integer, a half up.
        "set R0.20 0\nset IA0.2 5\nscans 1\nexpect R0.22 1\n"
        "set IA0.2 4\nscans 1\nexpect R0.22 0\n"
        "set IA0.2 -5\nscans 1\nexpect R0.22 0\n"
        "set IA0.2 -6\nscans 1\nexpect R0.22 -1\n");
    EXPECT_EQ(report.failed, 0) << firstFailure(report);
    EXPECT_EQ(report.passed, 20);
}

TEST(Analog01, ReadCurrentOutsideFourToTwentyMilliamperesIsNotOk) {
    const sim::ScenarioReport report = runAnalog01(
        analog01D45(";@block ReadCurrent Input=\"IA0.3\" Value_4mA=\"-32768\" Value_20mA=\"32767\" "
                    "Q=\"M0.3\" Current=\"R0.30\" Scaled_Value=\"R0.31\"\n"
                    ";@end\n"),
        "set IA0.3 3999\nscans 1\nexpect M0.3 0\nexpect R0.31 -32768\n"
        "set IA0.3 4000\nscans 1\nexpect M0.3 1\nexpect R0.31 -32768\n"
        "set IA0.3 20000\nscans 1\nexpect M0.3 1\nexpect R0.31 32767\n"
        "set IA0.3 20001\nscans 1\nexpect M0.3 0\nexpect R0.31 32767\n"
        // More than a register holds saturates, the calibrated value too.
        "set IA0.3 40000\nscans 1\nexpect M0.3 0\nexpect R0.30 32767\nexpect R0.31 32767\n"
        "set IA0.3 -40000\nscans 1\nexpect R0.30 -32768\nexpect R0.31 -32768\n");
    EXPECT_EQ(report.failed, 0) << firstFailure(report);
    EXPECT_EQ(report.passed, 13);
}

TEST(Analog01, TheThirtyTwoBitFormsScaleBeyondARegister) {
    const sim::ScenarioReport report = runAnalog01(
        analog01D45(";@block ReadCurrent_32 Input=\"IA0.1\" Value_4mA=\"0\" Value_20mA=\"1000000\" "
                    "Q=\"M0.1\" Current=\"DR0.40\" Scaled_Value=\"DR0.42\"\n"
                    ";@end\n"
                    ";@block ReadVoltage_32 Input=\"IA0.2\" Value_0V=\"DR0.44\" "
                    "Value_10V=\"-100000\" Q=\"M0.2\" Scaled_Value=\"DR0.46\"\n"
                    ";@end\n"),
        "set IA0.1 12000\nset IA0.2 2500\nset DR0.44 100000\nscans 1\n"
        "expect M0.1 1\nexpect DR0.40 12000\nexpect DR0.42 500000\n"
        "expect M0.2 1\nexpect DR0.46 50000\n"
        "set IA0.1 0\nset IA0.2 -10000\nscans 1\n"
        "expect M0.1 0\nexpect DR0.42 -250000\n"
        "expect M0.2 0\nexpect DR0.46 300000\n"
        "set IA0.1 2000000000\nscans 1\nexpect DR0.40 2000000000\n"
        "expect DR0.42 2147483647\n");
    EXPECT_EQ(report.failed, 0) << firstFailure(report);
    EXPECT_EQ(report.passed, 11);
}

TEST(Analog01, TwoInstancesReadTheirOwnInputs) {
    const sim::ScenarioReport report =
        runAnalog01(analog01D45(kSpeed + ";@block ReadCurrent Input=\"IA0.3\" Value_4mA=\"100\" "
                                         "Value_20mA=\"200\" Q=\"M0.3\" Scaled_Value=\"R0.31\"\n"
                                         ";@end\n"),
                    "set IA0.1 20000\nset IA0.3 12000\nscans 1\n"
                    "expect M0.1 1\nexpect Speed_Freq_Conv 488\nexpect M0.3 1\nexpect R0.31 150\n"
                    "set IA0.1 0\nscans 1\nexpect M0.1 0\nexpect M0.3 1\nexpect R0.31 150\n");
    EXPECT_EQ(report.failed, 0) << firstFailure(report);
    EXPECT_EQ(report.passed, 7);
}

TEST(Analog01, AWrongInstanceIsAnErrorAtItsRecord) {
    struct Case {
        std::string record;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {";@block ReadCurrent Input=\"IA0.1\" Value_20mA=\"488\" Q=\"M0.1\"",
         "9:1: ReadCurrent: input Value_4mA is not bound and has no default\n"},
        {";@block ReadCurrent Input=\"M0.5\" Value_4mA=\"0\" Value_20mA=\"488\"",
         "9:21: ReadCurrent: pin Input takes input, not 'M0.5'\n"},
        {";@block ReadCurrent Input=\"IA0.2\" Value_4mA=\"0\" Value_20mA=\"488\"",
         "9:22: ReadCurrent reads IA0.2 as a current input, but line 5 declares it a voltage "
         "input\n"},
        {";@block ReadCurrent Input=\"I0.2\" Value_4mA=\"0\" Value_20mA=\"488\"",
         "9:22: ReadCurrent: operand Input takes an analogue input (IA), not I0.2\n"},
        {";@block ReadVoltage_32 Input=\"IA0.2\" Value_0V=\"0\" Value_10V=\"R0.1\"",
         "9:51: ReadVoltage_32: pin Value_10V takes double-register or number, not 'R0.1'\n"},
    };
    for (const auto& c : cases) {
        const auto read =
            blocks::readProjectWithInstances(analog01D45(c.record + "\n;@end\n"), analog01());
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
