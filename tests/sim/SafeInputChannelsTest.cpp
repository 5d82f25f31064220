// SPDX-License-Identifier: GPL-3.0-or-later
#include "sim/SafeInputChannels.h"
#include "compiler/Compiler.h"
#include "project/ProjectFile.h"
#include "sim/Scenario.h"
#include "sim/Simulation.h"

#include <gtest/gtest.h>

#include <random>

using namespace rs;
using project::ChannelMonitoring;

namespace {

constexpr ChannelMonitoring kModes[] = {
    ChannelMonitoring::None, ChannelMonitoring::Monitoring, ChannelMonitoring::MonitoringDebounce,
    ChannelMonitoring::Simultaneous, ChannelMonitoring::SimultaneousDebounce};

} // namespace

// Whatever the channels do, in every mode: the input is never on unless both
// channels are closed, a fault keeps it off, and both channels open clear a
// fault. Without monitoring the input is exactly both channels.
TEST(SafeInputChannels, TheInputNeedsBothChannelsInEveryMode) {
    std::mt19937 random(20261203);
    for (ChannelMonitoring mode : kModes) {
        for (int run = 0; run < 200; ++run) {
            const std::int64_t limit = 10 + static_cast<std::int64_t>(random() % 500);
            sim::SafeInputChannels channels(mode, limit);
            channels.powerOn();
            std::int64_t now = 0;
            for (int step = 0; step < 200; ++step) {
                if (random() % 3 == 0)
                    channels.setChannel(1 + static_cast<int>(random() % 2), random() % 2 == 0);
                channels.update(now);
                const bool both = channels.channel(1) && channels.channel(2);
                const bool none = !channels.channel(1) && !channels.channel(2);
                ASSERT_FALSE(channels.input() && !both) << static_cast<int>(mode);
                ASSERT_FALSE(channels.input() && channels.fault());
                ASSERT_FALSE(none && channels.fault());
                if (mode == ChannelMonitoring::None) {
                    ASSERT_EQ(channels.input(), both);
                }
                now += 10;
            }
        }
    }
}

// Once a mode's window is over, an input that is on stays on exactly as long as
// both channels stay closed; one opening alone is a fault in every mode but none.
TEST(SafeInputChannels, OneChannelOpeningAloneIsAFaultOnceSettled) {
    for (ChannelMonitoring mode : kModes) {
        sim::SafeInputChannels channels(mode, 100);
        channels.setChannel(1, true);
        channels.setChannel(2, true);
        for (std::int64_t now = 0; now <= 300; now += 10)
            channels.update(now);
        ASSERT_TRUE(channels.input()) << static_cast<int>(mode);
        channels.setChannel(1, false);
        channels.update(310);
        channels.setChannel(1, true);
        channels.update(320);
        EXPECT_EQ(channels.input(), mode == ChannelMonitoring::None) << static_cast<int>(mode);
        EXPECT_EQ(channels.fault(), mode != ChannelMonitoring::None) << static_cast<int>(mode);
    }
}

TEST(SafeInputChannels, SimulationSetsBothChannelsAndReportsTheFirstFault) {
    const char* text = "! id_pluto_ASi:00=000000000000\n"
                       ";@asi_slave ASi0.7 type=\"safe_input\"\n"
                       ";@asi_slave ASi0.9 type=\"safe_input\"\n"
                       ";@asi_slave ASi0.12 type=\"nonsafe_std\"\n"
                       "! type_pluto:00=ASi,is3\n"
                       "! pgm_pluto:00\n"
                       "S0.0_0\n"
                       "M0.1 = ASi0.7\n";
    const auto compiled = compiler::compileText(text);
    ASSERT_EQ(compiled.errors(), 0);
    sim::Simulation simulation(compiled.images);
    const lang::Address slave7{lang::AddressKind::AsiInput, 0, 7};
    const lang::Address slave9{lang::AddressKind::AsiInput, 0, 9};
    const lang::Address chanf{lang::AddressKind::SystemRegister, 0, 16};
    EXPECT_TRUE(simulation.hasChannels(slave7));
    EXPECT_FALSE(simulation.hasChannels({lang::AddressKind::AsiInput, 0, 12, 1}));
    EXPECT_FALSE(simulation.setChannel({lang::AddressKind::AsiInput, 0, 8}, 1, true));
    simulation.set(slave7, 1);
    simulation.set(slave9, 1);
    simulation.scan();
    EXPECT_TRUE(simulation.channel(slave7, 1));
    EXPECT_TRUE(simulation.channel(slave7, 2));
    EXPECT_EQ(simulation.value({lang::AddressKind::Memory, 0, 1}), 1);
    simulation.setChannel(slave9, 2, false);
    simulation.setChannel(slave7, 1, false);
    simulation.scan();
    EXPECT_EQ(simulation.value(chanf), 7); // the first slave in fault
    EXPECT_EQ(simulation.value(slave7), 0);
    simulation.set(slave7, 0);
    simulation.scan();
    EXPECT_EQ(simulation.value(chanf), 9);
    simulation.restart(); // power on: channels open, no fault
    simulation.scan();
    EXPECT_EQ(simulation.value(chanf), 0);
    EXPECT_FALSE(simulation.channel(slave9, 1));
}

TEST(SafeInputChannels, AScenarioNamesAChannelOfADefinedSafeSlaveOnly) {
    const auto read = project::readProject("! id_pluto_ASi:00=000000000000\n"
                                           ";@asi_slave ASi0.3 type=\"safe_input\"\n"
                                           "! type_pluto:00=ASi,is3\n"
                                           "! ASi0.3=Door\n"
                                           "! pgm_pluto:00\n"
                                           "S0.0_0\n");
    const sim::OperandNames names(read.project);
    auto firstError = [&](std::string_view text) {
        const auto scenario = sim::parseScenario(text, names);
        return scenario.diagnostics.empty()
                   ? std::string()
                   : lang::formatDiagnostic("t.scn", scenario.diagnostics.front());
    };
    EXPECT_EQ(firstError("set Door.ch1 1\nset asi0.3.CH2 0\nexpect Door 0\n"), "");
    EXPECT_EQ(firstError("set ASi0.4.ch1 1\nexpect Door 0\n"),
              "t.scn:1:5: error: ASi0.4 is no safe input slave of the AS-i Options page; only "
              "those have the channels ch1 and ch2");
    EXPECT_EQ(firstError("set Door.ch1 2\nexpect Door 0\n"),
              "t.scn:1:14: error: ASi0.3 is a bit: its value is 0 or 1");
    EXPECT_EQ(firstError("expect Door.ch1 0\n").substr(0, 25), "t.scn:1:8: error: unknown");
}
