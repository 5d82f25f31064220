// SPDX-License-Identifier: GPL-3.0-or-later
#include "blocks/InstanceVariables.h"
#include "DiagnosticsText.h"
#include "project/ProjectFile.h"
#include "project/UnitText.h"

#include <gtest/gtest.h>

#include <sstream>

using rs::test::addressOf;

// Which of a unit's variables its block instances take, and where each
// instance stands in the unit's text.

using namespace rs;
using blocks::InstanceVariable;
using Role = InstanceVariable::Role;

namespace {

const std::string kVariablesHead = "! id_pluto:00=000000000000\n"
                                   "! type_pluto:00=A20,is3\n"
                                   "! I0.0=Door1A\n"
                                   "! pgm_pluto:00\n";

// EquivalentInputs as Rungsmith_Basics expands it, with its Fault left open.
const std::string kDoors =
    ";@block EquivalentInputs Channel1=\"Door1A\" Channel2=\"I0.1\" DiscrepancyTime=\"0s50\" "
    "Out=\"Q0.2\" lib=\"Rungsmith_Basics\" version=\"1.0\" #pin.Fault=\"M0.599\" "
    "#fault=\"M0.598\"\n"
    "S(M0.598) = (Door1A * /I0.1 + /Door1A * I0.1) * TON(0s50)\n"
    "R(M0.598) = /Door1A * /I0.1\n"
    "Q0.2 = Door1A * I0.1 * /M0.598\n"
    "M0.599 = M0.598\n"
    ";@end\n";

project::Project variablesProject(const std::string& code) {
    project::ProjectReadResult read = project::readProject(kVariablesHead + code);
    EXPECT_TRUE(read.ok()) << (read.diagnostics.empty() ? "" : read.diagnostics[0].message);
    return read.project;
}

std::string shown(const std::vector<InstanceVariable>& variables) {
    std::ostringstream out;
    for (const auto& v : variables)
        out << lang::toString(v.address) << ' ' << (v.role == Role::Pin ? "pin " : "#") << v.name
            << ' ' << v.blockType << ':' << v.line << '\n';
    return out.str();
}

// The line of the unit's text, counted from 1.
std::string lineOfUnitText(const project::Project& project, int line) {
    std::istringstream text(project::unitText(project, 0));
    std::string at;
    for (int i = 0; i < line && std::getline(text, at); ++i) {
    }
    return at;
}

TEST(InstanceVariables, PinsAndPrivatesWithTheBlockAndTheLineOfItsRecord) {
    const project::Project project = variablesProject("S0.0_0\nQ0.3 = I0.5\n" + kDoors);
    const auto variables = blocks::instanceVariables(project, 0);
    EXPECT_EQ(shown(variables), "I0.0 pin Channel1 EquivalentInputs:4\n"
                                "I0.1 pin Channel2 EquivalentInputs:4\n"
                                "Q0.2 pin Out EquivalentInputs:4\n"
                                "M0.599 #pin.Fault EquivalentInputs:4\n"
                                "M0.598 #fault EquivalentInputs:4\n")
        << "a time bound to a pin takes no variable";
    EXPECT_TRUE(lineOfUnitText(project, 4).starts_with(";@block EquivalentInputs"));
}

TEST(InstanceVariables, LinesFollowTheUnitsTextAcrossStepsAndBrokenRecords) {
    // The first record has no ;@end in its step: it is no instance, but it
    // is a line of the text all the same.
    const project::Project project = variablesProject(
        "S0.0_0\n;@block ResetLatch Enable=\"I0.3\"\n\nS0.1_00\n;comment\n" + kDoors +
        "S0.1_01\n;@block ResetLatch Enable=\"I0.4\" Reset=\"I0.5\" Out=\"Q0.3\" "
        "#on=\"M0.597\"\n;@end\n");
    const auto variables = blocks::instanceVariables(project, 0);
    ASSERT_EQ(variables.size(), 9u) << shown(variables);
    for (const auto& variable : variables)
        EXPECT_TRUE(
            lineOfUnitText(project, variable.line).starts_with(";@block " + variable.blockType))
            << shown(variables);
    EXPECT_EQ(variables.back(), (InstanceVariable{addressOf("M0.597"), Role::Private, "on",
                                                  "ResetLatch", variables.back().line}));
    EXPECT_GT(variables.back().line, variables.front().line);
}

TEST(InstanceVariables, AreListedAsTheVariablesPageListsThem) {
    const project::Project project = variablesProject(
        "S0.0_0\n;@block Counter Up=\"R0.5.3\" #count=\"DR0.146\" #other=\"M1.2\"\n"
        ";@end\n");
    EXPECT_EQ(shown(blocks::instanceVariables(project, 0)),
              "R0.5 pin Up Counter:3\nDR0.146 #count Counter:3\n")
        << "a register bit is its register; another unit's variable is not this unit's";
    EXPECT_TRUE(blocks::instanceVariables(project, 1).empty());
}

} // namespace
