// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/RemanentVariables.h"
#include "ProjectText.h"
#include "project/ProjectProperties.h"
#include "project/UnitSettings.h"

#include <gtest/gtest.h>

using namespace rs;
using lang::Address;
using lang::AddressKind;

namespace {

project::Project withUnit(target::UnitType type) {
    project::Project p = project::newProject("R", {}, false);
    project::UnitSettings unit;
    unit.station = 4;
    unit.type = type;
    EXPECT_FALSE(project::addUnit(p, unit));
    return p;
}

std::set<Address> registers(int first, int last, int station = 4) {
    std::set<Address> set;
    for (int i = first; i <= last; ++i)
        set.insert({AddressKind::Register, station, i});
    return set;
}

} // namespace

TEST(RemanentVariables, OnlyR100ToR131AndM100ToM131OnTypesThatHaveThem) {
    const auto& b46 = target::unitTypeInfo(target::UnitType::B46);
    EXPECT_TRUE(project::canBeRemanent(b46, {AddressKind::Register, 0, 100}));
    EXPECT_TRUE(project::canBeRemanent(b46, {AddressKind::Memory, 0, 131}));
    EXPECT_FALSE(project::canBeRemanent(b46, {AddressKind::Memory, 0, 99}));
    EXPECT_FALSE(project::canBeRemanent(b46, {AddressKind::Register, 0, 132}));
    EXPECT_FALSE(project::canBeRemanent(b46, {AddressKind::GlobalMemory, 0, 100}));
    EXPECT_FALSE(project::canBeRemanent(target::unitTypeInfo(target::UnitType::A16),
                                        {AddressKind::Register, 0, 100}));
}

TEST(RemanentVariables, AllRegistersLeaveNoRoomForMemories) {
    std::set<Address> selection = registers(100, 131);
    EXPECT_FALSE(project::checkRemanentSelection(selection));
    selection.insert({AddressKind::Memory, 4, 100});
    EXPECT_TRUE(project::checkRemanentSelection(selection));
    selection.erase({AddressKind::Register, 4, 131});
    EXPECT_FALSE(project::checkRemanentSelection(selection));
}

TEST(RemanentVariables, SetRemanentReplacesTheUnitsSelectionOrRefuses) {
    project::Project p = withUnit(target::UnitType::B46);
    ASSERT_FALSE(project::setRemanent(p, 4, registers(100, 103)));
    EXPECT_NE(textOf(p).find(";@unit 04 remanent=\"R100-R103\""), std::string::npos);
    const project::Project before = p;
    std::set<Address> bad = registers(100, 131);
    bad.insert({AddressKind::Memory, 4, 100});
    EXPECT_TRUE(project::setRemanent(p, 4, bad));
    EXPECT_TRUE(project::setRemanent(p, 4, registers(99, 100)));
    EXPECT_TRUE(project::setRemanent(p, 4, registers(100, 100, 5)));
    EXPECT_TRUE(p == before);
    ASSERT_FALSE(project::setRemanent(p, 4, {}));
    EXPECT_TRUE(p.remanentVariables.empty());
    project::Project a16 = withUnit(target::UnitType::A16);
    EXPECT_TRUE(project::setRemanent(a16, 4, registers(100, 100)));
}

TEST(RemanentVariables, ListsJoinRunsAndReadBack) {
    std::set<Address> set = registers(100, 103);
    set.insert({AddressKind::Register, 4, 110});
    set.insert({AddressKind::Memory, 4, 131});
    EXPECT_EQ(project::formatRemanentList(set, 4), "M131,R100-R103,R110");
    EXPECT_EQ(project::parseRemanentList("M131,R100-R103,R110", 4), set);
    EXPECT_EQ(project::formatRemanentList(set, 3), "");
    EXPECT_THROW(project::parseRemanentList("R100-M103", 4), project::RemanentListError);
    EXPECT_THROW(project::parseRemanentList("R103-R100", 4), project::RemanentListError);
    EXPECT_THROW(project::parseRemanentList("R100,", 4), project::RemanentListError);
    EXPECT_THROW(project::parseRemanentList("Q100", 4), project::RemanentListError);
}
