// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/AsiOptions.h"
#include "ProjectText.h"
#include "project/ProjectFile.h"
#include "project/UnitAsiOptions.h"
#include "project/UnitSettings.h"
#include "project/VariableTable.h"

#include <gtest/gtest.h>

using namespace rs;
using project::AsiMode;
using project::AsiSlave;
using project::AsiSlaveAddress;
using project::AsiSlaveType;
using project::ChannelMonitoring;

namespace {

constexpr std::string_view kAsiUnit = "$name Asi\n"
                                      "! id_pluto_ASi:00=000000000000\n"
                                      "! type_pluto:00=ASi,is2\n"
                                      "! pgm_pluto:00\n"
                                      "S0.0_0\n";

std::vector<std::string> asiLabels(const std::vector<lang::Address>& list) {
    std::vector<std::string> text;
    for (const auto& a : list)
        text.push_back(lang::toString(a));
    return text;
}

} // namespace

TEST(AsiOptions, SlaveVariablesFollowTheManualsTable) {
    const auto& asi = target::unitTypeInfo(target::UnitType::ASi);
    EXPECT_EQ(asiLabels(project::slaveVariables(asi, 0, {3, false}, AsiSlaveType::SafeInput)),
              (std::vector<std::string>{"ASi0.3", "ASq0.3.1", "ASq0.3.2", "ASq0.3.3", "ASq0.3.4"}));
    EXPECT_EQ(asiLabels(project::slaveVariables(asi, 0, {5, true}, AsiSlaveType::NonsafeAB)),
              (std::vector<std::string>{"ASi0.5B.1", "ASi0.5B.2", "ASi0.5B.3", "ASi0.5B.4",
                                        "ASq0.5B.1", "ASq0.5B.2", "ASq0.5B.3"}));
    EXPECT_EQ(project::slaveVariables(asi, 0, {7, false}, AsiSlaveType::NonsafeStandard).size(),
              8u);
    EXPECT_TRUE(project::slaveVariables(asi, 0, {7, false}, AsiSlaveType::SafeOutput).empty());
    // Slaves 1-15 of a Pluto AS-i are global safety inputs, 16-31 local.
    EXPECT_TRUE(target::isGlobal(asi, {lang::AddressKind::AsiInput, 0, 15}));
    EXPECT_FALSE(target::isGlobal(asi, {lang::AddressKind::AsiInput, 0, 16}));
    const auto& a20 = target::unitTypeInfo(target::UnitType::A20);
    EXPECT_TRUE(project::slaveVariables(a20, 0, {3, false}, AsiSlaveType::SafeInput).empty());
}

TEST(AsiOptions, ABSlaveSharesOnlyWithAnABSlave) {
    project::AsiOptions options;
    ASSERT_FALSE(
        project::setSlave(options, {4, false}, project::defaultSlave(AsiSlaveType::NonsafeAB)));
    ASSERT_FALSE(
        project::setSlave(options, {4, true}, project::defaultSlave(AsiSlaveType::NonsafeAB)));
    EXPECT_EQ(options.slaves.size(), 2u);
    // A safe input fills the whole address: the B slave goes with it.
    ASSERT_FALSE(
        project::setSlave(options, {4, false}, project::defaultSlave(AsiSlaveType::SafeInput)));
    EXPECT_EQ(options.slaves.size(), 1u);
    EXPECT_TRUE(
        project::setSlave(options, {4, true}, project::defaultSlave(AsiSlaveType::NonsafeAB)));
    EXPECT_TRUE(
        project::setSlave(options, {6, true}, project::defaultSlave(AsiSlaveType::SafeInput)));
    EXPECT_TRUE(
        project::setSlave(options, {32, false}, project::defaultSlave(AsiSlaveType::SafeInput)));
    AsiSlave slow = project::defaultSlave(AsiSlaveType::SafeInput);
    slow.monitoring = ChannelMonitoring::Simultaneous;
    slow.timeLimitMs = 20'000;
    EXPECT_TRUE(project::setSlave(options, {8, false}, slow));
    EXPECT_EQ(options.slaves.size(), 1u);
}

TEST(AsiOptions, AtMostSixteenBlockSlaves) {
    project::AsiOptions options;
    for (int n = 1; n <= 16; ++n)
        ASSERT_FALSE(
            project::setSlave(options, {n, false},
                              project::defaultSlave(n % 2 ? AsiSlaveType::SafeOutput
                                                          : AsiSlaveType::PlutoAsSafeInput)));
    EXPECT_TRUE(
        project::setSlave(options, {17, false}, project::defaultSlave(AsiSlaveType::SafeOutput)));
    // Changing one of the sixteen stays possible.
    EXPECT_FALSE(project::setSlave(options, {1, false},
                                   project::defaultSlave(AsiSlaveType::PlutoAsSafeInput)));
}

TEST(AsiOptions, UraxMonitorsItsOwnChannels) {
    project::AsiOptions options;
    AsiSlave urax = project::defaultSlave(AsiSlaveType::SafeInput);
    urax.model = "URAX-A1R";
    urax.monitoring = ChannelMonitoring::Simultaneous;
    ASSERT_FALSE(project::setSlave(options, {2, false}, urax));
    EXPECT_EQ(options.slaves.at({2, false}).monitoring, ChannelMonitoring::None);
    EXPECT_FALSE(project::hasProfile(AsiSlaveType::SafeInput, "URAX-A1R"));
    urax.model = "URAX-C1";
    ASSERT_FALSE(project::setSlave(options, {2, false}, urax));
    EXPECT_EQ(options.slaves.at({2, false}).monitoring, ChannelMonitoring::Simultaneous);
    urax.model = "URAX-Z9";
    EXPECT_TRUE(project::setSlave(options, {2, false}, urax));
}

TEST(AsiOptions, RecordsKeepEverySettingThroughTheFile) {
    project::Project p = projectFrom(kAsiUnit);
    project::AsiOptions options;
    options.mode = AsiMode::MonitorSlaveExtra;
    options.slaveAddress = 12;
    options.optimisation = project::AsiOptimisation::DisturbanceImmunity;
    AsiSlave door = project::defaultSlave(AsiSlaveType::SafeInput);
    door.monitoring = ChannelMonitoring::SimultaneousDebounce;
    door.timeLimitMs = 250;
    door.parameter = 0x7;
    door.profile = {0x7, 0xB, 0x1, 0xE};
    ASSERT_FALSE(project::setSlave(options, {3, false}, door));
    ASSERT_FALSE(project::setSlave(options, {9, false},
                                   project::defaultSlave(AsiSlaveType::CombinedTransaction)));
    ASSERT_FALSE(
        project::setSlave(options, {9, true}, project::defaultSlave(AsiSlaveType::NonsafeAB)));
    project::setAsiOptions(p, 0, options);
    const std::string text = textOf(p);
    EXPECT_NE(
        text.find(";@asi 00 mode=\"monitor_slave_extra\" address=\"12\" optimize=\"immunity\""),
        std::string::npos)
        << text;
    EXPECT_NE(text.find(";@asi_slave ASi0.3 type=\"safe_input\" model=\"General\" param=\"7\" "
                        "profile=\"S-7.B.1\" id1=\"E\" monitoring=\"simultaneous_debounce\" "
                        "time_limit_ms=\"250\""),
              std::string::npos)
        << text;
    EXPECT_NE(text.find(";@asi_slave ASi0.9B type=\"nonsafe_ab\""), std::string::npos) << text;
    EXPECT_TRUE(isStable(p));
    EXPECT_EQ(project::asiOptionsOf(projectFrom(text), 0), options);
    // The defaults write nothing.
    project::setAsiOptions(p, 0, {});
    EXPECT_EQ(textOf(p).find(";@asi"), std::string::npos);
}

TEST(AsiOptions, MalformedRecordsAreErrorsAtTheirLine) {
    const auto errorOf = [](std::string_view record) {
        std::string text(kAsiUnit);
        text.insert(text.find("! pgm_pluto"), std::string(record) + "\n");
        for (const auto& d : project::readProject(text).diagnostics)
            if (d.severity == lang::Severity::Error)
                return std::to_string(d.line) + ": " + d.message;
        return std::string("no error");
    };
    EXPECT_EQ(errorOf(";@asi 00 mode=\"boss\""),
              "4: @asi mode must be one of master, monitor, monitor_slave, monitor_slave_extra, "
              "unused, not 'boss'");
    EXPECT_EQ(errorOf(";@asi 00 mode=\"monitor_slave\" address=\"40\""),
              "4: @asi address must be a slave address 1-31, not '40'");
    EXPECT_EQ(errorOf(";@asi_slave ASi0.32 type=\"safe_input\"").substr(0, 36),
              "4: @asi_slave needs a slave address ");
    EXPECT_EQ(errorOf(";@asi_slave ASi0.3 type=\"safe_input\" profile=\"S-0.X.F\"").substr(0, 35),
              "4: @asi_slave profile must be writt");
    EXPECT_EQ(errorOf(";@asi_slave ASi0.3B type=\"safe_input\""),
              "4: @asi_slave ASi0.3B: slave 3B: a B address takes only an A/B slave, beside an "
              "A/B slave");
    EXPECT_EQ(errorOf(";@asi_slave ASi0.3 type=\"safe_input\" monitoring=\"simultaneous\" "
                      "time_limit_ms=\"5\""),
              "4: @asi_slave ASi0.3: slave 3: the time limit must be 0.01-10 s");
}

TEST(AsiOptions, VariablesPageListsTheDefinedSlavesAndWhatIsInUse) {
    project::Project p = projectFrom(std::string(kAsiUnit) + "ASq0.20.2=ASi0.7\n");
    auto listed = [&](project::VariableGroup group) {
        std::vector<std::string> text;
        for (const auto& row : project::variableTable(p, 0, group))
            if (row.address.kind == lang::AddressKind::AsiInput ||
                row.address.kind == lang::AddressKind::AsiOutput)
                text.push_back(lang::toString(row.address));
        return text;
    };
    // Nothing defined: only what the code uses.
    EXPECT_EQ(listed(project::VariableGroup::SafetyInputs), (std::vector<std::string>{"ASi0.7"}));
    EXPECT_EQ(listed(project::VariableGroup::AsiSlaves), (std::vector<std::string>{"ASq0.20.2"}));
    project::AsiOptions options;
    ASSERT_FALSE(project::setSlave(options, {2, false},
                                   project::defaultSlave(AsiSlaveType::NonsafeStandard)));
    ASSERT_FALSE(
        project::setSlave(options, {3, false}, project::defaultSlave(AsiSlaveType::SafeInput)));
    project::setAsiOptions(p, 0, options);
    EXPECT_EQ(listed(project::VariableGroup::SafetyInputs),
              (std::vector<std::string>{"ASi0.3", "ASi0.7"}));
    EXPECT_EQ(listed(project::VariableGroup::AsiSlaves).size(), 8u + 4u + 1u);
}

TEST(AsiOptions, AChangeToATypeWithoutASiDropsTheOptions) {
    project::Project p = projectFrom(kAsiUnit);
    project::AsiOptions options;
    options.mode = AsiMode::MonitorOnly;
    project::setAsiOptions(p, 0, options);
    auto settings = *project::unitSettings(p, 0);
    settings.type = target::UnitType::B42ASi;
    ASSERT_FALSE(project::changeUnit(p, settings));
    EXPECT_EQ(project::asiOptionsOf(p, 0).mode, AsiMode::MonitorOnly);
    settings.type = target::UnitType::A20;
    ASSERT_FALSE(project::changeUnit(p, settings));
    EXPECT_TRUE(p.asiOptions.empty());
}
