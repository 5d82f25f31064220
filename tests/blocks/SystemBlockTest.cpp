// SPDX-License-Identifier: GPL-3.0-or-later
// System blocks (docs/block-libraries.md): an instance expands to a ;@system
// call with every pin bound, which compiles and simulates.
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

blocks::LoadedLibrary loaded(const std::string& text) {
    const auto read = blocks::readLibrary(text);
    EXPECT_TRUE(read.ok()) << (read.diagnostics.empty() ? "" : read.diagnostics[0].message);
    return {read.library, QStringLiteral("test.rslib"), blocks::LibraryOrigin::User};
}

// The shipped Rungsmith_System.
blocks::LibrarySet shipped() {
    std::ifstream file(RUNGSMITH_LIBRARIES "/Rungsmith_System.rslib", std::ios::binary);
    std::stringstream text;
    text << file.rdbuf();
    blocks::LibrarySet set;
    set.libraries.push_back(loaded(text.str()));
    return set;
}

// Unit 0 exports R0.5 and DR0.10; unit 1 reads them.
std::string twoUnits(const std::string& unitOneCode) {
    return "! id_pluto:00=000000000000\n"
           ";@var R0.5 export=\"yes\"\n"
           ";@var DR0.10 export=\"yes\"\n"
           "! type_pluto:00=A20,is3\n"
           "! id_pluto:01=000000000001\n"
           "! type_pluto:01=A20,is3\n"
           "! pgm_pluto:00\n"
           "S0.0_0\n"
           "(R0.5 = 42)\n"
           "(DR0.10 = 100000)\n"
           "! pgm_pluto:01\n"
           "S1.0_0\n" +
           unitOneCode;
}

sim::ScenarioReport simulate(const blocks::ProjectWithInstances& read,
                             const std::vector<compiler::UnitImage>& images,
                             const std::string& scenario) {
    sim::Simulation simulation(images);
    return sim::runScenario(
        "t.scn", sim::parseScenario(scenario, sim::OperandNames(read.read.project)), simulation);
}

} // namespace

TEST(SystemBlock, ABodylessRegisterValidIsExpandedCompiledAndSimulated) {
    const auto result = blocks::readProjectWithInstances(
        twoUnits(";@block RegisterValid Input=\"R0.5\" Valid=\"M1.1\"\n"
                 ";@end\n"
                 ";@block DRegisterValid Input=\"DR0.10\" Valid=\"M1.2\" Value=\"DR1.20\"\n"
                 ";@end\n"),
        shipped());
    ASSERT_TRUE(result.read.ok()) << diagnosticsText(result.read.diagnostics);
    EXPECT_TRUE(result.expanded);
    const std::string text = project::writeProject(result.read.project);
    // Every pin bound: the open Value to a register of the instance's own.
    EXPECT_NE(text.find(";@block RegisterValid Input=\"R0.5\" Valid=\"M1.1\" "
                        "lib=\"Rungsmith_System\" version=\"1.0\" #pin.Value=\"R1.149\"\n"
                        ";@system RegisterValid Input=\"R0.5\" Valid=\"M1.1\" Value=\"R1.149\"\n"
                        ";@end\n"
                        ";@block DRegisterValid Input=\"DR0.10\" Valid=\"M1.2\" Value=\"DR1.20\" "
                        "lib=\"Rungsmith_System\" version=\"1.0\"\n"
                        ";@system DRegisterValid Input=\"DR0.10\" Valid=\"M1.2\" "
                        "Value=\"DR1.20\"\n"
                        ";@end\n"),
              std::string::npos)
        << text;

    const compiler::CompileResult compiled =
        blocks::compileProject(result.read.project, result.read.diagnostics);
    ASSERT_EQ(compiled.errors(), 0) << diagnosticsText(compiled.diagnostics);
    const sim::ScenarioReport report =
        simulate(result, compiled.images,
                 "scans 2\nexpect M1.1 1\nexpect R1.149 42\nexpect M1.2 1\n"
                 "expect DR1.20 100000\n");
    EXPECT_EQ(report.failed, 0) << (report.failures.empty() ? "" : report.failures.front());
    EXPECT_EQ(report.passed, 4);

    // The saved text compiles to the same image, and reads back unchanged
    // without warnings, with or without the library.
    EXPECT_EQ(compiler::compileText(text).images, compiled.images);
    for (const auto& set : {shipped(), blocks::LibrarySet{}}) {
        const auto again = blocks::readProjectWithInstances(text, set);
        EXPECT_TRUE(again.read.diagnostics.empty()) << diagnosticsText(again.read.diagnostics);
        EXPECT_FALSE(again.expanded);
        EXPECT_EQ(project::writeProject(again.read.project), text);
    }
}

TEST(SystemBlock, AnAddressACallAlreadyWritesIsNoInstancesPrivateVariable) {
    const auto result = blocks::readProjectWithInstances(
        twoUnits(";@system RegisterValid Input=\"R0.5\" Valid=\"M1.599\" Value=\"R1.149\"\n"
                 ";@block RegisterValid Input=\"R0.5\" Valid=\"M1.1\"\n"
                 ";@end\n"),
        shipped());
    ASSERT_TRUE(result.read.ok()) << diagnosticsText(result.read.diagnostics);
    EXPECT_NE(project::writeProject(result.read.project).find("#pin.Value=\"R1.148\""),
              std::string::npos);
}

namespace {

const char* kTestLibrary = R"(rungsmith-library 1
library Test
version 1.0
block Lamp
    kind system
    version 1.0
    system RegisterValid
    description en RegisterValid with a lamp that is on while Input is not valid.
    pin Input in register primary
    pin Valid out bit primary
    pin Value out register secondary
    pin Lamp out bit secondary
    body {Lamp} = /{Valid}
block Newer
    kind system
    version 1.0
    system ReadTemperature
    description en An instruction this Rungsmith does not have.
    pin Input in register primary
block Misfit
    kind system
    version 1.0
    system RegisterValid
    description en Valid is a register here.
    pin Input in register primary
    pin Valid out register primary
    pin Value out register secondary
)";

blocks::LibrarySet testLibrary() {
    blocks::LibrarySet set;
    set.libraries.push_back(loaded(kTestLibrary));
    return set;
}

} // namespace

TEST(SystemBlock, ABodyFollowsTheCall) {
    const auto result = blocks::readProjectWithInstances(
        twoUnits(";@block Lamp Input=\"R0.5\" Valid=\"M1.1\" Value=\"R1.6\" Lamp=\"Q1.10\"\n"
                 ";@end\n"),
        testLibrary());
    ASSERT_TRUE(result.read.ok()) << diagnosticsText(result.read.diagnostics);
    const std::string text = project::writeProject(result.read.project);
    EXPECT_NE(text.find(";@system RegisterValid Input=\"R0.5\" Valid=\"M1.1\" Value=\"R1.6\"\n"
                        "Q1.10 = /M1.1\n"
                        ";@end\n"),
              std::string::npos)
        << text;
    const compiler::CompileResult compiled =
        blocks::compileProject(result.read.project, result.read.diagnostics,
                               {.warnUnconfiguredIo = false, .onlyUnit = {}});
    ASSERT_EQ(compiled.errors(), 0) << diagnosticsText(compiled.diagnostics);
    const sim::ScenarioReport report =
        simulate(result, compiled.images, "scans 2\nexpect M1.1 1\nexpect Q1.10 0\n");
    EXPECT_EQ(report.failed, 0) << (report.failures.empty() ? "" : report.failures.front());
}

TEST(SystemBlock, ABlockWhoseCallCannotBeMadeIsAnErrorAtTheRecord) {
    struct Case {
        std::string record;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {";@block Newer Input=\"R0.5\"",
         "13:1: Newer: system instruction 'ReadTemperature' is not one of this Rungsmith's; "
         "did you mean ReadVoltage, ReadCurrent, ReadVoltage_32, ReadCurrent_32?\n"},
        {";@block Misfit Input=\"R0.5\" Valid=\"R1.1\"",
         "13:1: Misfit: the block does not fit its system instruction RegisterValid, which needs "
         "the pin Valid out bit\n"},
        {";@block Lamp Input=\"M0.5\" Valid=\"M1.1\"",
         "13:14: Lamp: pin Input takes register, system-register or number, not 'M0.5'\n"},
    };
    for (const auto& c : cases) {
        const auto result =
            blocks::readProjectWithInstances(twoUnits(c.record + "\n;@end\n"), testLibrary());
        EXPECT_EQ(diagnosticsText(result.read.diagnostics), c.expected) << c.record;
    }
}
