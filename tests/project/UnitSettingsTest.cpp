// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/UnitSettings.h"
#include "ProjectText.h"
#include "compiler/Compiler.h"
#include "project/IoOptions.h"
#include "project/ProjectFile.h"
#include "project/ProjectProperties.h"
#include "project/VariableTable.h"

#include <gtest/gtest.h>

using namespace rs;
using project::UnitSettings;
using target::UnitType;

namespace {

UnitSettings unit(int station, UnitType type, int instructionSet = 3,
                  std::string idfix = std::string(project::kNoIdfix)) {
    UnitSettings settings;
    settings.station = station;
    settings.type = type;
    settings.instructionSet = instructionSet;
    settings.idfix = std::move(idfix);
    return settings;
}

int compileErrors(const project::Project& p) {
    return compiler::compileText(project::writeProject(p)).errors();
}

} // namespace

TEST(UnitSettings, ANewProjectWithUnitsIsTheManualsText) {
    project::Project p = project::newProject("Press", "Two presses", true);
    EXPECT_EQ(textOf(p),
              "$name Press\n;@project description=\"Two presses\" include_source=\"yes\"\n");

    ASSERT_FALSE(project::addUnit(p, unit(1, UnitType::B46, 3, "0000abcd1234")));
    UnitSettings first = unit(0, UnitType::A20, 2);
    first.description = "Cabinet A";
    ASSERT_FALSE(project::addUnit(p, first));
    EXPECT_EQ(textOf(p), "$name Press\n"
                         ";@project description=\"Two presses\" include_source=\"yes\"\n"
                         "\n"
                         "! id_pluto:00=000000000000\n"
                         ";@unit 00 description=\"Cabinet A\"\n"
                         "! type_pluto:00=A20,is2\n"
                         "! id_pluto_Double:01=0000ABCD1234\n"
                         "! type_pluto:01=B46,is3\n"
                         "\n"
                         "! pgm_pluto:00\n"
                         "\n"
                         "S0.0_0\n"
                         "\n"
                         "! pgm_pluto:01\n"
                         "\n"
                         "S1.0_0\n");
    EXPECT_TRUE(isStable(p));
    EXPECT_EQ(compileErrors(p), 0);
    EXPECT_EQ(p.stations(), (std::vector<int>{0, 1}));
}

TEST(UnitSettings, UnitsAreReadBackAsTheyWereAdded) {
    project::Project p = project::newProject("P", {}, false);
    UnitSettings asi = unit(7, UnitType::ASi, 3, "FFFF00007FA3");
    asi.description = "AS-i master";
    ASSERT_FALSE(project::addUnit(p, asi));
    const auto read = project::unitSettings(projectFrom(textOf(p)), 7);
    ASSERT_TRUE(read);
    EXPECT_EQ(*read, asi);
    EXPECT_EQ(project::unitTypeOf(p, 7).family, lang::UnitFamily::ASi);
}

TEST(UnitSettings, AUnitWithoutTypeLineIsItsFamilysBaseTypeWithInstructionSet2) {
    const project::Project p = projectFrom("! id_pluto_Double:04=000000000000\n! pgm_pluto:04\n"
                                           "S4.0_0\n! pgm_pluto:05\nS5.0_0\n");
    const auto declared = project::unitSettings(p, 4);
    ASSERT_TRUE(declared);
    EXPECT_EQ(declared->type, UnitType::B46);
    EXPECT_EQ(declared->instructionSet, 2);
    EXPECT_TRUE(declared->declared);
    const auto undeclared = project::unitSettings(p, 5);
    ASSERT_TRUE(undeclared);
    EXPECT_FALSE(undeclared->declared);
    EXPECT_FALSE(project::unitSettings(p, 6));
}

TEST(UnitSettings, OnlyFreeStationsAndLegalSettingsAreAccepted) {
    project::Project p = project::newProject("P", {}, false);
    ASSERT_FALSE(project::addUnit(p, unit(0, UnitType::A20)));
    const project::Project before = p;
    EXPECT_TRUE(project::addUnit(p, unit(0, UnitType::B46)));
    EXPECT_TRUE(project::addUnit(p, unit(32, UnitType::B46)));
    EXPECT_TRUE(project::addUnit(p, unit(1, UnitType::B46, 3, "12345")));
    EXPECT_TRUE(project::addUnit(p, unit(1, UnitType::B46, 3, "00000000000G")));
    EXPECT_TRUE(project::addUnit(p, unit(1, UnitType::A16, 3)));
    EXPECT_TRUE(project::addUnit(p, unit(1, UnitType::B46, 4)));
    EXPECT_TRUE(p == before);

    const auto free = project::freeStations(p);
    EXPECT_EQ(free.size(), 31u);
    EXPECT_EQ(free.front(), 1);
    EXPECT_FALSE(project::supportsInstructionSet3(UnitType::B16));
    EXPECT_TRUE(project::supportsInstructionSet3(UnitType::O2));
}

TEST(UnitSettings, ChangingTheTypeDropsWhatTheNewTypeCannotHave) {
    project::Project p = project::newProject("P", {}, false);
    ASSERT_FALSE(project::addUnit(p, unit(0, UnitType::B46)));
    // Q0.20 exists on a B46, not on an A20; Q0.4 is a B46's local safety output.
    project::setTerminalSetting(p, {project::TerminalKind::Configurable, 0, 20},
                                {project::SignalType::Output, project::SignalShape::Static});
    project::setTerminalSetting(p, {project::TerminalKind::Configurable, 0, 12},
                                {project::SignalType::Input, project::SignalShape::APulse});
    ASSERT_FALSE(project::setVariableName(p, {lang::AddressKind::Output, 0, 4}, "Valve"));
    ASSERT_FALSE(project::setVariableName(p, {lang::AddressKind::DoubleRegister, 0, 4}, "Pos"));
    ASSERT_FALSE(project::setVariableName(p, {lang::AddressKind::Input, 0, 12}, "Start"));

    // Q0.20's declaration, Valve and Pos go; I0.12's declaration and name stay.
    EXPECT_EQ(project::removedByChange(p, unit(0, UnitType::A20, 2)), 3);
    EXPECT_EQ(project::removedByChange(p, unit(0, UnitType::S46, 3)), 0);
    ASSERT_FALSE(project::changeUnit(p, unit(0, UnitType::A20, 2)));
    const std::string text = textOf(p);
    EXPECT_NE(text.find("! id_pluto:00=000000000000\n! type_pluto:00=A20,is2\n"), std::string::npos)
        << text;
    EXPECT_EQ(text.find("Q0.20"), std::string::npos) << text;
    EXPECT_EQ(text.find("Valve"), std::string::npos) << text;
    EXPECT_EQ(text.find("Pos"), std::string::npos) << text; // no double registers in set 2
    EXPECT_NE(text.find("! I0.12,a_pulse"), std::string::npos) << text;
    EXPECT_NE(text.find("! I0.12=Start"), std::string::npos) << text;
    EXPECT_TRUE(isStable(p));
    EXPECT_EQ(compileErrors(p), 0);
}

TEST(UnitSettings, RemovingAUnitTakesItsCodeNamesAndRecords) {
    project::Project p = project::newProject("P", {}, false);
    ASSERT_FALSE(project::addUnit(p, unit(0, UnitType::A20)));
    ASSERT_FALSE(project::addUnit(p, unit(1, UnitType::A20)));
    ASSERT_FALSE(project::setVariableName(p, {lang::AddressKind::Input, 1, 0}, "EStop1"));
    project::setVariableDescription(p, {lang::AddressKind::Input, 1, 0}, "Stop");
    project::Project onlyFirst = project::newProject("P", {}, false);
    ASSERT_FALSE(project::addUnit(onlyFirst, unit(0, UnitType::A20)));

    project::removeUnit(p, 1);
    EXPECT_EQ(textOf(p), textOf(onlyFirst));
    EXPECT_TRUE(isStable(p));
}

// Manual Part 1, 5.1: "IDFIX-PROG" beside an IDFIX number and No IDFIX,
// kept as the unit record's idfix="prog" and gone with the unit.
TEST(UnitSettings, AnIdfixProgIsKeptInTheUnitRecord) {
    project::Project p = project::newProject("Press", "", false);
    UnitSettings prog = unit(0, UnitType::B46, 3, "0000ABCD1234");
    prog.idfixProg = true;
    ASSERT_FALSE(project::addUnit(p, prog));
    const std::string text = textOf(p);
    EXPECT_NE(text.find("! id_pluto_Double:00=0000ABCD1234\n;@unit 00 idfix=\"prog\"\n"),
              std::string::npos)
        << text;
    const project::Project read = projectFrom(text);
    EXPECT_TRUE(project::unitSettings(read, 0)->idfixProg);
    EXPECT_TRUE(isStable(read));
    EXPECT_EQ(compileErrors(read), 0);

    prog.idfixProg = false;
    ASSERT_FALSE(project::changeUnit(p, prog));
    EXPECT_EQ(textOf(p).find("idfix="), std::string::npos);
    prog.idfixProg = true;
    ASSERT_FALSE(project::changeUnit(p, prog));
    project::removeUnit(p, 0);
    EXPECT_TRUE(p.idfixProg.empty());

    const auto wrong =
        project::readProject("$name P\n! id_pluto:00=000000000000\n;@unit 00 idfix=\"yes\"\n");
    ASSERT_EQ(wrong.diagnostics.size(), 1u);
    EXPECT_EQ(wrong.diagnostics[0].line, 3);
    EXPECT_NE(wrong.diagnostics[0].message.find("idfix can only be prog"), std::string::npos);
}
