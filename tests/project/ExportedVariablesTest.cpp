// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/ExportedVariables.h"
#include "ProjectText.h"
#include "project/ProjectProperties.h"
#include "project/UnitSettings.h"

#include <gtest/gtest.h>

using namespace rs;
using lang::Address;
using lang::AddressKind;

namespace {

project::Project withUnits(int count, int instructionSet = 3) {
    project::Project p = project::newProject("Bus", {}, false);
    for (int station = 0; station < count; ++station) {
        project::UnitSettings unit;
        unit.station = station;
        unit.type = target::UnitType::B46;
        unit.instructionSet = instructionSet;
        EXPECT_FALSE(project::addUnit(p, unit));
    }
    return p;
}

} // namespace

TEST(ExportedVariables, OnlyLocalVariablesOfListedKindsWithInstructionSet3) {
    project::Project p = withUnits(1);
    EXPECT_FALSE(project::checkExportable(p, {AddressKind::Memory, 0, 3}));
    EXPECT_FALSE(project::checkExportable(p, {AddressKind::Register, 0, 3}));
    EXPECT_FALSE(project::checkExportable(p, {AddressKind::DoubleRegister, 0, 4}));
    EXPECT_FALSE(project::checkExportable(p, {AddressKind::Output, 0, 4}));  // local safety
    EXPECT_FALSE(project::checkExportable(p, {AddressKind::Output, 0, 20})); // non-safety
    EXPECT_FALSE(project::checkExportable(p, {AddressKind::Input, 0, 30}));  // local input
    EXPECT_TRUE(project::checkExportable(p, {AddressKind::Input, 0, 0}));    // global
    EXPECT_TRUE(project::checkExportable(p, {AddressKind::GlobalMemory, 0, 0}));
    EXPECT_TRUE(project::checkExportable(p, {AddressKind::SystemMemory, 0, 1}));
    EXPECT_TRUE(project::checkExportable(p, {AddressKind::Memory, 1, 3})); // no unit 1
    project::Project set2 = withUnits(1, 2);
    EXPECT_TRUE(project::checkExportable(set2, {AddressKind::Memory, 0, 3}));
}

TEST(ExportedVariables, TelegramPairsAreCountedAsTheManualSays) {
    project::Project p = withUnits(1);
    for (int i = 0; i < 32; ++i)
        ASSERT_FALSE(project::setExported(p, {AddressKind::Memory, 0, i}, true));
    EXPECT_EQ(project::telegramPairs(p, 0), 1); // 32 Booleans
    ASSERT_FALSE(project::setExported(p, {AddressKind::Memory, 0, 32}, true));
    EXPECT_EQ(project::telegramPairs(p, 0), 2);
    ASSERT_FALSE(project::setExported(p, {AddressKind::Register, 0, 0}, true));
    EXPECT_EQ(project::telegramPairs(p, 0), 2); // 33 + 16 bits fit in two pairs
    ASSERT_FALSE(project::setExported(p, {AddressKind::DoubleRegister, 0, 10}, true));
    EXPECT_EQ(project::telegramPairs(p, 0), 3);
    ASSERT_FALSE(project::setExported(p, {AddressKind::DoubleRegister, 0, 12}, true));
    EXPECT_EQ(project::telegramPairs(p, 0), 4);
    const project::Project full = p;
    const auto refused = project::setExported(p, {AddressKind::Register, 0, 1}, true);
    ASSERT_TRUE(refused);
    EXPECT_NE(refused->find("4"), std::string::npos);
    EXPECT_TRUE(p == full);
    ASSERT_FALSE(project::setExported(p, {AddressKind::DoubleRegister, 0, 12}, false));
    EXPECT_EQ(project::telegramPairs(p, 0), 3);
    EXPECT_TRUE(isStable(p));
}

TEST(ExportedVariables, AProjectAddsAtMostSixteenPairs) {
    project::Project p = withUnits(5);
    for (int station = 0; station < 4; ++station)
        for (int i = 0; i < 4; ++i)
            ASSERT_FALSE(
                project::setExported(p, {AddressKind::DoubleRegister, station, i * 2}, true));
    EXPECT_EQ(project::telegramPairs(p), 16);
    EXPECT_TRUE(project::setExported(p, {AddressKind::Memory, 4, 0}, true));
    EXPECT_EQ(project::telegramPairs(p, 4), 0);
}
