// SPDX-License-Identifier: GPL-3.0-or-later
#include "blocks/BodyTemplate.h"
#include "blocks/LibraryReader.h"
#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "sim/ScenarioRunner.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

using namespace rs;

namespace {

const blocks::BlockLibrary& basics() {
    static const blocks::BlockLibrary library = [] {
        std::ifstream file(RUNGSMITH_LIBRARIES "/Rungsmith_Basics.rslib", std::ios::binary);
        std::stringstream text;
        text << file.rdbuf();
        return blocks::readLibrary(text.str()).library;
    }();
    return library;
}

// The block's body with its placeholders bound, as an expansion will be.
std::string expand(const std::string& blockName, const std::map<std::string, std::string>& bound) {
    const blocks::BlockDefinition* block = basics().findBlock(blockName);
    EXPECT_NE(block, nullptr) << blockName;
    std::string text;
    for (const std::string& line : block->body)
        text +=
            blocks::substitute(line,
                               [&](const blocks::Placeholder& placeholder) {
                                   return bound.at(placeholder.isPrivate ? "#" + placeholder.name
                                                                         : placeholder.name);
                               })
                .text +
            "\n";
    return text;
}

sim::ScenarioReport run(const std::string& code, const std::string& scenarioText) {
    const std::string text = "! id_pluto:00=000000000000\n! type_pluto:00=A20,is3\n"
                             "! pgm_pluto:00\nS0.0_0\n" +
                             code;
    const compiler::CompileResult compiled = compiler::compileText(text);
    EXPECT_EQ(compiled.errors(), 0) << text;
    const project::ProjectReadResult read = project::readProject(text);
    const sim::OperandNames names(read.project);
    sim::Simulation simulation(compiled.images);
    return sim::runScenario("t.scn", sim::parseScenario(scenarioText, names), simulation);
}

} // namespace

// The definitions docs/block-libraries.md gives, checked on the simulator.
TEST(StandardLibraryBehaviour, ResetLatchNeedsANewPressOfReset) {
    const std::string code = expand("ResetLatch", {{"Enable", "I0.0"},
                                                   {"Reset", "I0.1"},
                                                   {"Out", "Q0.0"},
                                                   {"ResetLamp", "Q0.1"},
                                                   {"#on", "M0.10"}});
    const sim::ScenarioReport report = run(code, "set I0.1 1\nscans 3\nset I0.0 1\nscans 3\n"
                                                 "expect Q0.0 0\nexpect Q0.1 1\n"
                                                 "set I0.1 0\nscans 2\nset I0.1 1\nscans 1\n"
                                                 "expect Q0.0 1\nexpect Q0.1 0\n"
                                                 "set I0.1 0\nscans 5\nexpect Q0.0 1\n"
                                                 "set I0.0 0\nscans 1\nexpect Q0.0 0\n"
                                                 "expect Q0.1 0\n");
    EXPECT_EQ(report.failed, 0) << (report.failures.empty() ? "" : report.failures.front());
    EXPECT_EQ(report.passed, 7);
}

TEST(StandardLibraryBehaviour, EquivalentInputsLatchesADiscrepancyUntilBothAreOff) {
    const std::string code = expand("EquivalentInputs", {{"Channel1", "I0.2"},
                                                         {"Channel2", "I0.3"},
                                                         {"DiscrepancyTime", "0s50"},
                                                         {"Out", "Q0.2"},
                                                         {"Fault", "Q0.3"},
                                                         {"#fault", "M0.20"}});
    const sim::ScenarioReport report =
        run(code, "set I0.2 1\nset I0.3 1\nscans 1\nexpect Q0.2 1\n"
                  // A difference shorter than the time is no fault.
                  "set I0.3 0\nscans 40\nexpect Q0.3 0\nexpect Q0.2 0\n"
                  "set I0.3 1\nscans 1\nexpect Q0.2 1\n"
                  // One of 0.5 s is, and it holds while a channel is on.
                  "set I0.3 0\nexpect Q0.3 1 within 600ms\n"
                  "set I0.3 1\nscans 2\nexpect Q0.2 0\nexpect Q0.3 1\n"
                  "set I0.2 0\nset I0.3 0\nscans 1\nexpect Q0.3 0\n"
                  "set I0.2 1\nset I0.3 1\nscans 1\nexpect Q0.2 1\n");
    EXPECT_EQ(report.failed, 0) << (report.failures.empty() ? "" : report.failures.front());
    EXPECT_EQ(report.passed, 9);
}
