// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/VariableTable.h"
#include "ProjectText.h"
#include "project/ProjectProperties.h"
#include "project/UnitSettings.h"

#include <gtest/gtest.h>

using namespace rs;
using lang::Address;
using lang::AddressKind;
using project::VariableGroup;

namespace {

project::Project twoUnits(int instructionSet = 3) {
    project::Project p = project::newProject("Vars", {}, false);
    project::UnitSettings unit;
    unit.type = target::UnitType::B46;
    unit.instructionSet = instructionSet;
    EXPECT_FALSE(project::addUnit(p, unit));
    unit.station = 1;
    unit.type = target::UnitType::A20;
    EXPECT_FALSE(project::addUnit(p, unit));
    return p;
}

std::vector<std::string> addresses(const std::vector<Address>& list) {
    std::vector<std::string> text;
    for (const auto& a : list)
        text.push_back(lang::toString(a));
    return text;
}

} // namespace

TEST(VariableTable, GroupsFollowTheTypeAndInstructionSet) {
    const auto& b46 = target::unitTypeInfo(target::UnitType::B46);
    EXPECT_EQ(project::variableGroups(b46, 3),
              (std::vector<VariableGroup>{
                  VariableGroup::SafetyInputs, VariableGroup::SafetyOutputs,
                  VariableGroup::NonSafetyOutputs, VariableGroup::GlobalMemories,
                  VariableGroup::Memories, VariableGroup::Registers, VariableGroup::DoubleRegisters,
                  VariableGroup::SystemMemories, VariableGroup::SystemRegisters}));
    EXPECT_EQ(project::variableGroups(b46, 2).size(), 8u);
    const auto& asi = target::unitTypeInfo(target::UnitType::ASi);
    EXPECT_EQ(project::variableGroups(asi, 2).back(), VariableGroup::AsiSlaves);
    const auto& b22 = target::unitTypeInfo(target::UnitType::B22);
    EXPECT_EQ(project::variableGroups(b22, 3)[1], VariableGroup::NonSafetyOutputs);
}

TEST(VariableTable, VariablesAreTheManualsRanges) {
    const auto& b46 = target::unitTypeInfo(target::UnitType::B46);
    const auto outputs = addresses(project::variablesIn(b46, 5, 3, VariableGroup::SafetyOutputs));
    EXPECT_EQ(outputs, (std::vector<std::string>{"Q5.0", "Q5.1", "Q5.2", "Q5.3", "Q5.4", "Q5.5"}));
    EXPECT_EQ(project::variablesIn(b46, 5, 3, VariableGroup::SafetyInputs).size(), 16u + 24u);
    EXPECT_EQ(project::variablesIn(b46, 5, 3, VariableGroup::Memories).size(), 600u);
    const auto doubles = project::variablesIn(b46, 5, 3, VariableGroup::DoubleRegisters);
    EXPECT_EQ(doubles.size(), 75u);
    EXPECT_EQ(lang::toString(doubles.back()), "DR5.148");
    const auto& asi = target::unitTypeInfo(target::UnitType::ASi);
    EXPECT_EQ(project::variablesIn(asi, 0, 2, VariableGroup::Memories).size(), 150u);
    const auto safe = addresses(project::variablesIn(asi, 0, 2, VariableGroup::SafetyInputs));
    EXPECT_EQ(safe.at(8), "ASi0.1");
    EXPECT_EQ(safe.back(), "ASi0.31");
    const auto slaves = addresses(project::variablesIn(asi, 0, 2, VariableGroup::AsiSlaves));
    EXPECT_EQ(slaves.size(), 496u);
    EXPECT_EQ(slaves.at(4), "ASi0.1B.1");
    const auto& d20 = target::unitTypeInfo(target::UnitType::D20);
    EXPECT_EQ(addresses(project::variablesIn(d20, 0, 3, VariableGroup::SafetyInputs)).front(),
              "IA0.0");
}

TEST(VariableTable, RowsCarryNamesDescriptionsAndAttributes) {
    project::Project p = projectFrom("$name Example, manual\n"
                                     "! id_pluto_Double:00=000000000000\n"
                                     ";@unit 00 remanent=\"M100\"\n"
                                     ";@var M0.1 description=\"Latched\" export=\"yes\"\n"
                                     "! type_pluto:00=B46,is3\n"
                                     "! I0.0=MuteSensor1\n"
                                     "! pgm_pluto:00\n"
                                     "! M0.1=Latched\n"
                                     "S0.0_0\n"
                                     "Latched = MuteSensor1 * SM_1Hz\n");
    const auto inputs = project::variableTable(p, 0, VariableGroup::SafetyInputs);
    EXPECT_EQ(inputs[0].name, "MuteSensor1");
    EXPECT_TRUE(inputs[0].global);
    EXPECT_TRUE(inputs[0].used);
    EXPECT_FALSE(inputs[1].used);
    EXPECT_FALSE(inputs[16].global); // I0.20, local
    const auto memories = project::variableTable(p, 0, VariableGroup::Memories);
    EXPECT_EQ(memories[1].name, "Latched");
    EXPECT_EQ(memories[1].description, "Latched");
    EXPECT_TRUE(memories[1].exported);
    EXPECT_TRUE(memories[100].remanent);
    EXPECT_FALSE(memories[1].global);
    const auto system = project::variableTable(p, 0, VariableGroup::SystemMemories);
    EXPECT_EQ(system[3].systemName, "SM_1Hz");
    EXPECT_TRUE(system[3].used);
    EXPECT_FALSE(system[3].systemFunction.empty());
}

TEST(VariableTable, GlobalNamesGoBeforeTheCodeLocalOnesIntoTheUnitsCode) {
    project::Project p = twoUnits();
    ASSERT_FALSE(project::setVariableName(p, {AddressKind::Input, 0, 12}, "EStop"));
    ASSERT_FALSE(project::setVariableName(p, {AddressKind::Input, 0, 0}, "MuteSensor1"));
    ASSERT_FALSE(project::setVariableName(p, {AddressKind::Memory, 1, 0}, "MutingActive"));
    ASSERT_FALSE(project::setVariableName(p, {AddressKind::Output, 1, 14}, "IndReset"));
    EXPECT_EQ(textOf(p), "$name Vars\n"
                         "\n"
                         "! id_pluto_Double:00=000000000000\n"
                         "! type_pluto:00=B46,is3\n"
                         "! id_pluto:01=000000000000\n"
                         "! type_pluto:01=A20,is3\n"
                         "! I0.0=MuteSensor1\n"
                         "! I0.12=EStop\n"
                         "\n"
                         "! pgm_pluto:00\n"
                         "\n"
                         "S0.0_0\n"
                         "\n"
                         "! pgm_pluto:01\n"
                         "\n"
                         "! Q1.14=IndReset\n"
                         "! M1.0=MutingActive\n"
                         "S1.0_0\n");
    EXPECT_TRUE(isStable(p));
    EXPECT_EQ(project::variableName(p, {AddressKind::Memory, 1, 0}), "MutingActive");
}

TEST(VariableTable, RenamingKeepsTheDeclarationsPlaceAndAnEmptyNameRemovesIt) {
    project::Project p = projectFrom("! id_pluto:00=000000000000\n"
                                     "! pgm_pluto:00\n"
                                     "! I0.3,static\n"
                                     "! M0.0=Old                     ; keep me\n"
                                     "! M0.5=Other\n"
                                     "S0.0_0\n"
                                     "Q0.2 = Old\n");
    ASSERT_FALSE(project::setVariableName(p, {AddressKind::Memory, 0, 0}, "Renamed"));
    EXPECT_NE(textOf(p).find("! M0.0=Renamed                 ; keep me\n! M0.5=Other"),
              std::string::npos)
        << textOf(p);
    EXPECT_NE(textOf(p).find("Q0.2 = Renamed\n"), std::string::npos) << textOf(p);
    ASSERT_FALSE(project::setVariableName(p, {AddressKind::Memory, 0, 5}, ""));
    EXPECT_EQ(textOf(p).find("Other"), std::string::npos);
    ASSERT_FALSE(project::setVariableName(p, {AddressKind::Memory, 0, 3}, "Between"));
    EXPECT_NE(textOf(p).find("! M0.0=Renamed                 ; keep me\n! M0.3=Between\nS0.0_0"),
              std::string::npos)
        << textOf(p);
}

TEST(VariableTable, NamesFollowTheManualsRules) {
    project::Project p = twoUnits(3);
    const Address m{AddressKind::Memory, 0, 1};
    EXPECT_TRUE(project::checkVariableName(p, m, "1st"));
    EXPECT_TRUE(project::checkVariableName(p, m, "_x"));
    EXPECT_TRUE(project::checkVariableName(p, m, "a.b")); // set 3: no dots
    EXPECT_TRUE(project::checkVariableName(p, m, "Q0.1"));
    EXPECT_TRUE(project::checkVariableName(p, m, "SM_Ditto"));
    EXPECT_FALSE(project::checkVariableName(p, m, "Nödstopp_2"));
    EXPECT_FALSE(project::checkVariableName(p, m, ""));
    project::Project set2 = twoUnits(2);
    EXPECT_FALSE(project::checkVariableName(set2, m, "a.b"));
}

TEST(VariableTable, ANameIsUniqueInItsScope) {
    project::Project p = twoUnits();
    ASSERT_FALSE(project::setVariableName(p, {AddressKind::Memory, 0, 1}, "Busy"));
    // Another unit may use the same local name; the same unit may not.
    EXPECT_FALSE(project::setVariableName(p, {AddressKind::Memory, 1, 1}, "busy"));
    const project::Project before = p;
    const auto refused = project::setVariableName(p, {AddressKind::Memory, 0, 2}, "BUSY");
    ASSERT_TRUE(refused);
    EXPECT_NE(refused->find("M0.1"), std::string::npos);
    // A global name clashes with the local names of every unit.
    EXPECT_TRUE(project::setVariableName(p, {AddressKind::Input, 0, 0}, "Busy"));
    EXPECT_TRUE(p == before);
    EXPECT_TRUE(isStable(p));
}

TEST(VariableTable, DescriptionsAreSetAndCleared) {
    project::Project p = twoUnits();
    const Address r{AddressKind::Register, 1, 7};
    project::setVariableDescription(p, r, "Speed, \"rpm\"");
    EXPECT_NE(textOf(p).find(";@var R1.7 description=\"Speed, \\\"rpm\\\"\""), std::string::npos);
    EXPECT_TRUE(isStable(p));
    project::setVariableDescription(p, r, "");
    EXPECT_TRUE(p.variableDescriptions.empty());
}

TEST(VariableTable, GroupOfFindsTheTab) {
    const auto& b46 = target::unitTypeInfo(target::UnitType::B46);
    EXPECT_EQ(project::groupOf(b46, 3, {AddressKind::Output, 0, 4}), VariableGroup::SafetyOutputs);
    EXPECT_EQ(project::groupOf(b46, 3, {AddressKind::Output, 0, 21}),
              VariableGroup::NonSafetyOutputs);
    EXPECT_EQ(project::groupOf(b46, 2, {AddressKind::DoubleRegister, 0, 4}), std::nullopt);
    EXPECT_EQ(project::groupOf(b46, 3, {AddressKind::Memory, 0, 600}), std::nullopt);
}
