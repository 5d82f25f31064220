// SPDX-License-Identifier: GPL-3.0-or-later
#include "DiagnosticsText.h"
#include "blocks/LibraryReader.h"
#include "blocks/ProjectInstances.h"
#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "sim/ScenarioRunner.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace rs;
using rs::test::diagnosticsText;

namespace {

// A library for the tests: a latch with a default-1 enable, a register
// output, a timer with a time of 0 and one of 0s50 by default, and a block
// that needs many memories.
const char* kExpansionLibrary = R"(rungsmith-library 1
library Test
version 1.0
block Latch
    kind macro
    version 2.0
    description en Q is set by S while Enable, reset by R.
    pin S in bit primary
    pin R in bit primary default=0
    pin Enable in bit secondary default=1
    pin Q out bit primary
    pin Count out register secondary
    private q memory
    body S({#q}) = {S} * {Enable}
    body R({#q}) = {R}
    body {Q} = {#q}
    body ({Count}++) = P({S})
block Delay
    kind macro
    version 1.0
    description en Fast follows In after Short, Slow after Long.
    pin In in bit primary
    pin Short in time secondary default=0s00
    pin Long in time secondary default=0s50
    pin Fast out bit primary
    pin Slow out bit primary
    timers 2
    body {Fast} = {In} * TON({Short})
    body {Slow} = {In} * TON({Long})
block Greedy
    kind macro
    version 1.0
    description en Needs 250 memories.
    pin In in bit primary
)";

std::string greedyLibrary() {
    std::string text = kExpansionLibrary;
    for (int i = 0; i < 250; ++i)
        text += "    private m" + std::to_string(i) + " memory\n";
    for (int i = 0; i < 250; ++i)
        text +=
            "    body M0." + std::to_string(i % 8) + " = {In} * {#m" + std::to_string(i) + "}\n";
    return text;
}

blocks::LibrarySet expansionLibraries() {
    blocks::LibrarySet set;
    const auto read = blocks::readLibrary(greedyLibrary());
    EXPECT_TRUE(read.ok()) << (read.diagnostics.empty() ? "" : read.diagnostics[0].message);
    set.libraries.push_back(
        {read.library, QStringLiteral("test.rslib"), blocks::LibraryOrigin::User});
    return set;
}

const std::string kExpansionHead = "! id_pluto:00=000000000000\n"
                                   "! type_pluto:00=A20,is3\n"
                                   "! I0.0=Start\n"
                                   "! pgm_pluto:00\n"
                                   "S0.0_0\n";

blocks::ProjectWithInstances read(const std::string& code) {
    return blocks::readProjectWithInstances(kExpansionHead + code, expansionLibraries());
}

TEST(InstanceExpansion, ABodylessRecordIsExpandedAndRecordsWhatItWasGiven) {
    const auto result = read(";@block Latch S=\"Start\" R=\"I0.1\" Q=\"Q0.2\"\n"
                             ";@end\n"
                             "Q0.3 = I0.2\n");
    ASSERT_TRUE(result.read.ok()) << diagnosticsText(result.read.diagnostics);
    EXPECT_TRUE(result.expanded);
    const std::string text = project::writeProject(result.read.project);
    // Private memories and registers come from the top, below nothing the unit
    // uses, never remanent; an unbound default-1 input is set in the first scan.
    EXPECT_NE(text.find(";@block Latch S=\"Start\" R=\"I0.1\" Q=\"Q0.2\" lib=\"Test\" "
                        "version=\"2.0\" #pin.Enable=\"M0.599\" #pin.Count=\"R0.149\" "
                        "#q=\"M0.598\"\n"
                        "S(M0.599) = /M0.599\n"
                        "S(M0.598) = Start * M0.599\n"
                        "R(M0.598) = I0.1\n"
                        "Q0.2 = M0.598\n"
                        "(R0.149++) = P(Start)\n"
                        ";@end\n"
                        "Q0.3 = I0.2\n"),
              std::string::npos)
        << text;
}

TEST(InstanceExpansion, TheSavedExpansionReadsBackUnchangedWithoutWarnings) {
    const auto first = read(";@block Latch S=\"Start\" Q=\"Q0.2\"\n;@end\n"
                            ";@block Latch S=\"I0.1\" Q=\"Q0.3\"\n;@end\n");
    ASSERT_TRUE(first.read.ok()) << diagnosticsText(first.read.diagnostics);
    const std::string saved = project::writeProject(first.read.project);
    const auto again = blocks::readProjectWithInstances(saved, expansionLibraries());
    EXPECT_TRUE(again.read.diagnostics.empty()) << diagnosticsText(again.read.diagnostics);
    EXPECT_FALSE(again.expanded);
    EXPECT_EQ(project::writeProject(again.read.project), saved);
    // Without the library the saved file is still the same program.
    const auto alone = blocks::readProjectWithInstances(saved, blocks::LibrarySet{});
    EXPECT_TRUE(alone.read.diagnostics.empty()) << diagnosticsText(alone.read.diagnostics);
    EXPECT_EQ(project::writeProject(alone.read.project), saved);
}

TEST(InstanceExpansion, TwoInstancesGetPrivateVariablesOfTheirOwnAndKeepTheirOwnState) {
    const auto result = read(";@block Latch S=\"I0.0\" R=\"I0.1\" Q=\"Q0.2\"\n;@end\n"
                             ";@block Latch S=\"I0.2\" R=\"I0.3\" Q=\"Q0.3\"\n;@end\n");
    ASSERT_TRUE(result.read.ok()) << diagnosticsText(result.read.diagnostics);
    const std::string text = project::writeProject(result.read.project);
    const compiler::CompileResult compiled = compiler::compileText(text);
    ASSERT_EQ(compiled.errors(), 0) << diagnosticsText(compiled.diagnostics);
    sim::Simulation simulation(compiled.images);
    const sim::OperandNames names(result.read.project);
    const sim::ScenarioReport report =
        sim::runScenario("two.scn",
                         sim::parseScenario("set I0.0 1\nscans 2\nset I0.0 0\nscans 2\n"
                                            "expect Q0.2 1\nexpect Q0.3 0\n"
                                            "set I0.2 1\nscans 1\nset I0.1 1\nscans 1\n"
                                            "expect Q0.2 0\nexpect Q0.3 1\n",
                                            names),
                         simulation);
    EXPECT_EQ(report.failed, 0) << (report.failures.empty() ? "" : report.failures.front());
    EXPECT_EQ(report.passed, 4);
}

TEST(InstanceExpansion, AnOpenTimeOfZeroIsARegisterNothingWritesAndOtherTimesAreTheirDefault) {
    // TON(0s00) does not compile: the time 0 is a register holding 0.
    const auto result = read(";@block Delay In=\"Start\" Fast=\"Q0.2\" Slow=\"Q0.3\"\n;@end\n");
    ASSERT_TRUE(result.read.ok()) << diagnosticsText(result.read.diagnostics);
    const std::string text = project::writeProject(result.read.project);
    EXPECT_NE(text.find(";@block Delay In=\"Start\" Fast=\"Q0.2\" Slow=\"Q0.3\" lib=\"Test\" "
                        "version=\"1.0\" #pin.Short=\"R0.149\"\n"
                        "Q0.2 = Start * TON(R0.149)\n"
                        "Q0.3 = Start * TON(0s50)\n"
                        ";@end\n"),
              std::string::npos)
        << text;
    const compiler::CompileResult compiled = compiler::compileText(text);
    ASSERT_EQ(compiled.errors(), 0) << diagnosticsText(compiled.diagnostics);
    sim::Simulation simulation(compiled.images);
    const sim::OperandNames names(result.read.project);
    const sim::ScenarioReport report =
        sim::runScenario("delay.scn",
                         sim::parseScenario("set I0.0 1\nscans 1\nexpect Q0.2 1\nexpect Q0.3 0\n"
                                            "run 490ms\nexpect Q0.3 0\nscans 1\nexpect Q0.3 1\n",
                                            names),
                         simulation);
    EXPECT_EQ(report.failed, 0) << (report.failures.empty() ? "" : report.failures.front());
    EXPECT_EQ(report.passed, 4);
}

TEST(InstanceExpansion, RecordedPrivateVariablesAreKept) {
    const auto result = read(";@block Latch S=\"I0.0\" Q=\"Q0.2\" #q=\"M0.7\" #pin.Enable=\"M0.8\" "
                             "#pin.Count=\"R0.9\"\n;@end\n");
    ASSERT_TRUE(result.read.ok()) << diagnosticsText(result.read.diagnostics);
    const std::string text = project::writeProject(result.read.project);
    EXPECT_NE(text.find("S(M0.7) = I0.0 * M0.8\n"), std::string::npos) << text;
    EXPECT_NE(text.find("(R0.9++) = P(I0.0)\n"), std::string::npos) << text;
}

TEST(InstanceExpansion, BadCallsAreErrorsAtTheirRecords) {
    struct Case {
        std::string code;
        std::string message; // at line 6, the first record
        int column = 1;      // of the binding it concerns, else of the record
    };
    const Case cases[] = {
        {";@block Latch S=\"I0.0\" Q=\"Q0.2\" Speed=\"R0.1\"\n;@end\n",
         "Latch: no pin 'Speed'; its pins are S, R, Enable, Q, Count", 33},
        {";@block Latch Q=\"Q0.2\"\n;@end\n", "Latch: input S is not bound and has no default"},
        {";@block Latch S=\"R0.1\" Q=\"Q0.2\"\n;@end\n",
         "Latch: pin S takes input, output, memory, global-memory, system-memory or "
         "register-bit, not 'R0.1'",
         15},
        {";@block Latch S=\"I0.0\" Q=\"Nobody\"\n;@end\n",
         "Latch: pin Q: 'Nobody' is neither an address nor a name unit 0 sees", 24},
        {";@block Latch S=\"I0.0\" S=\"I0.1\" Q=\"Q0.2\"\n;@end\n",
         "@block Latch: pin 'S' is bound twice", 24},
        {";@block Unknown X=\"I0.0\"\n;@end\n", "unknown block 'Unknown'"},
        {";@block Latch S=\"I0.0\" Q=\"Q0.2\" lib=\"Other\"\n;@end\n",
         "unknown block 'Latch' in library 'Other'"},
        {";@block Latch S=\"I0.0\" Q=\"Q0.2\"\nQ0.3 = I0.1\n",
         "@block Latch has no ;@end before the step ends"},
        {";@end\n", "@end without a ;@block before it"},
        {";@block\n;@end\n",
         "@block needs the block's name, as in ;@block ResetLatch Enable=\"I0.0\""},
        {";@block Latch S=\"I0.0\" Q=\"Q0.2\"\n;@block Latch S=\"I0.1\" Q=\"Q0.3\"\n;@end\n",
         "@block Latch has no ;@end before the next ;@block; an instance cannot hold another"},
    };
    for (const auto& c : cases) {
        const auto result = read(c.code);
        EXPECT_FALSE(result.read.ok()) << c.code;
        ASSERT_FALSE(result.read.diagnostics.empty()) << c.code;
        const auto& first = result.read.diagnostics.front();
        EXPECT_EQ(first.line, 6) << c.code;
        EXPECT_EQ(first.column, c.column) << c.code;
        EXPECT_EQ(first.message, c.message) << c.code;
    }
}

TEST(InstanceExpansion, AUnitWithoutFreeMemoriesLeftSaysSo) {
    // The A20 has 600 memories, 32 of them remanent: two Greedy instances fit.
    const auto result = read(";@block Greedy In=\"I0.0\"\n;@end\n"
                             ";@block Greedy In=\"I0.1\"\n;@end\n"
                             ";@block Greedy In=\"I0.2\"\n;@end\n");
    const auto& d = result.read.diagnostics;
    ASSERT_EQ(lang::errorCount(d), 1) << diagnosticsText(d);
    EXPECT_EQ(d.front().line, 10);
    EXPECT_EQ(d.front().message.rfind("Greedy: unit 0 has no free memory left for the "
                                      "instance's m",
                                      0),
              0u)
        << d.front().message;
}

TEST(InstanceExpansion, EditedStatementsAreKeptWithAWarningAndAnUnknownBlockWithStatementsIsFine) {
    const auto first = read(";@block Latch S=\"Start\" Q=\"Q0.2\"\n;@end\n");
    std::string saved = project::writeProject(first.read.project);
    ASSERT_NE(saved.find("\nQ0.2 = M0."), std::string::npos) << saved;
    saved.insert(saved.find("\nQ0.2 = M0.") + 8, "/");
    const auto edited = blocks::readProjectWithInstances(saved, expansionLibraries());
    ASSERT_EQ(edited.read.diagnostics.size(), 1u) << diagnosticsText(edited.read.diagnostics);
    EXPECT_EQ(edited.read.diagnostics[0].severity, lang::Severity::Warning);
    EXPECT_EQ(edited.read.diagnostics[0].line, 6);
    EXPECT_NE(edited.read.diagnostics[0].message.find("edited by hand"), std::string::npos);
    EXPECT_EQ(project::writeProject(edited.read.project), saved) << "nothing is lost";

    std::string unknown = saved;
    unknown.replace(unknown.find(";@block Latch"), 13, ";@block Gone");
    const auto kept = blocks::readProjectWithInstances(unknown, expansionLibraries());
    EXPECT_TRUE(kept.read.diagnostics.empty()) << diagnosticsText(kept.read.diagnostics);
}

TEST(InstanceExpansion, AnotherVersionOfTheBlockIsPointedOut) {
    const auto first = read(";@block Latch S=\"Start\" Q=\"Q0.2\"\n;@end\n");
    std::string saved = project::writeProject(first.read.project);
    saved.replace(saved.find("version=\"2.0\""), 13, "version=\"1.0\"");
    const auto older = blocks::readProjectWithInstances(saved, expansionLibraries());
    ASSERT_EQ(older.read.diagnostics.size(), 1u) << diagnosticsText(older.read.diagnostics);
    EXPECT_EQ(older.read.diagnostics[0].message,
              "Latch is version 2.0 in its library; this instance was made by 1.0");
}

} // namespace
