// SPDX-License-Identifier: GPL-3.0-or-later
#include "target/UnitType.h"

#include <gtest/gtest.h>

using namespace rs;
using lang::Address;
using lang::AddressKind;

TEST(UnitTypes, EveryTypeOfTheManualsIsThereInOrder) {
    const char* names[] = {"A16", "A20", "B16", "B20", "S20", "B22",    "D20",
                           "O2",  "B46", "S46", "D45", "ASi", "B42_ASi"};
    ASSERT_EQ(target::unitTypes().size(), std::size(names));
    for (std::size_t i = 0; i < std::size(names); ++i) {
        EXPECT_EQ(target::unitTypes()[i].name, names[i]);
        EXPECT_EQ(&target::unitTypeInfo(static_cast<target::UnitType>(i)), &target::unitTypes()[i]);
    }
    EXPECT_EQ(target::findUnitType("b42_asi")->display, "B42 AS-i");
    EXPECT_EQ(target::findUnitType("X99"), nullptr);
}

TEST(UnitTypes, VariablesFollowTheManualsTables) {
    const auto& a20 = target::unitTypeInfo(target::UnitType::A20);
    EXPECT_TRUE(target::hasVariable(a20, {AddressKind::Input, 0, 17}, 3));
    EXPECT_FALSE(target::hasVariable(a20, {AddressKind::Input, 0, 8}, 3));
    EXPECT_FALSE(target::hasVariable(a20, {AddressKind::Output, 0, 4}, 3));
    EXPECT_TRUE(target::hasVariable(a20, {AddressKind::Memory, 0, 599}, 2));
    EXPECT_FALSE(target::hasVariable(a20, {AddressKind::GlobalMemory, 0, 12}, 3));
    EXPECT_FALSE(target::hasVariable(a20, {AddressKind::DoubleRegister, 0, 3}, 3));
    EXPECT_TRUE(target::hasVariable(a20, {AddressKind::DoubleRegister, 0, 148}, 3));

    const auto& b46 = target::unitTypeInfo(target::UnitType::B46);
    EXPECT_TRUE(target::hasVariable(b46, {AddressKind::Output, 0, 5}, 3));
    EXPECT_TRUE(target::hasVariable(b46, {AddressKind::Input, 0, 47}, 3));
    EXPECT_FALSE(target::isGlobal(b46, {AddressKind::Input, 0, 20}));
    EXPECT_TRUE(target::isGlobal(b46, {AddressKind::Output, 0, 3}));
    EXPECT_FALSE(target::isGlobal(b46, {AddressKind::Output, 0, 4}));

    const auto& asi = target::unitTypeInfo(target::UnitType::ASi);
    EXPECT_FALSE(target::hasVariable(asi, {AddressKind::Memory, 0, 150}, 2));
    EXPECT_TRUE(target::hasVariable(asi, {AddressKind::Memory, 0, 150}, 3));
    EXPECT_TRUE(target::hasVariable(asi, {AddressKind::AsiInput, 0, 31, 4, true}, 3));
    EXPECT_TRUE(target::isGlobal(asi, {AddressKind::AsiInput, 0, 15}));
    EXPECT_FALSE(target::isGlobal(asi, {AddressKind::AsiInput, 0, 16}));

    const auto& b42 = target::unitTypeInfo(target::UnitType::B42ASi);
    EXPECT_TRUE(target::hasVariable(b42, {AddressKind::GlobalMemory, 0, 27}, 3));
    EXPECT_FALSE(target::hasVariable(b42, {AddressKind::Output, 0, 0}, 3) &&
                 target::isGlobal(b42, {AddressKind::Output, 0, 0}));

    const auto& d45 = target::unitTypeInfo(target::UnitType::D45);
    EXPECT_TRUE(target::hasVariable(d45, {AddressKind::AnalogInput, 0, 7}, 3));
    EXPECT_FALSE(target::hasVariable(d45, {AddressKind::Input, 0, 27}, 3));
}

TEST(UnitTypes, SystemVariablesAndTheirAccess) {
    const auto& a20 = target::unitTypeInfo(target::UnitType::A20);
    const auto& b46 = target::unitTypeInfo(target::UnitType::B46);
    EXPECT_EQ(target::systemVariable(a20, {AddressKind::SystemMemory, 0, 84})->name, "SM_PlutoB");
    EXPECT_EQ(target::systemVariable(b46, {AddressKind::SystemMemory, 0, 15})->name, "SM_PlutoB");
    EXPECT_EQ(target::systemVariable(a20, {AddressKind::SystemRegister, 0, 42})->name,
              "SR_Q16_Current");
    EXPECT_EQ(target::systemVariable(b46, {AddressKind::SystemRegister, 0, 42}), nullptr);
    EXPECT_EQ(target::systemVariable(a20, {AddressKind::SystemRegister, 0, 10})->access,
              target::Access::Write);
    EXPECT_EQ(target::systemVariable(a20, {AddressKind::SystemMemory, 0, 9})->access,
              target::Access::Read);
    EXPECT_EQ(target::systemVariable(a20, {AddressKind::SystemMemory, 0, 131})->name,
              "SM_Pluto31_Present");
}

TEST(UnitTypes, OptionsOfTheFamilies) {
    EXPECT_TRUE(target::unitTypeInfo(target::UnitType::A20).testPulsesCanBeDisabled);
    EXPECT_FALSE(target::unitTypeInfo(target::UnitType::B46).testPulsesCanBeDisabled);
    EXPECT_TRUE(target::unitTypeInfo(target::UnitType::D45).remanent);
    EXPECT_FALSE(target::unitTypeInfo(target::UnitType::O2).remanent);
    EXPECT_EQ(target::baseType(lang::UnitFamily::Double), target::UnitType::B46);
}
