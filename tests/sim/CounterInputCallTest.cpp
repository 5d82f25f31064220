// SPDX-License-Identifier: GPL-3.0-or-later
// HS_SpeedCount_Up and HS_SpeedCount_Dir as the simulator runs them
// (docs/image-format.md, "System instructions"), in each of its tiers.
#include "SimulationFixture.h"
#include "SimulatorTier.h"

#include <gtest/gtest.h>

#include <climits>
#include <ostream>

using rs::test::MachineCodeSetting;
using rs::test::Simulated;
using rs::test::SimulatorTier;
using namespace rs;

namespace {

// A D45 counting up on IA0.0 and up and down on the pair IA0.2, IA0.3.
const char* kCounterProgram = "! id_pluto_Double:00=000000000000\n"
                              "! type_pluto:00=D45,is3\n"
                              "! pgm_pluto:00\n"
                              "! IA0.0,counter_up\n"
                              "! IA0.2,counter_updown\n"
                              "! IA0.3,counter_updown\n"
                              "S0.0_0\n"
                              ";@system HS_SpeedCount_Up Input=\"IA0.0\" Valid=\"M0.0\" "
                              "EdgePer10ms=\"R0.0\" PulsePerSec=\"R0.1\"\n"
                              ";@system HS_SpeedCount_Dir Input_A=\"IA0.2\" Input_B=\"IA0.3\" "
                              "Valid=\"M0.1\" EdgePer10ms=\"R0.2\" PulsePerSec=\"R0.3\"\n";

class CounterInputCall : public testing::TestWithParam<SimulatorTier> {
protected:
    CounterInputCall() : m_setting(GetParam() == SimulatorTier::MachineCode), s(kCounterProgram) {
        s.simulation->unit(0)->setEagerConduction(GetParam() == SimulatorTier::MarkingInterpreter);
    }

    // Valid, EdgePer10ms and PulsePerSec after a scan at `hertz`.
    struct Speed {
        std::int64_t valid, edgesPer10ms, pulsesPerSecond;
        friend bool operator==(const Speed&, const Speed&) = default;
        friend std::ostream& operator<<(std::ostream& out, const Speed& s) {
            return out << "Valid " << s.valid << ", EdgePer10ms " << s.edgesPer10ms
                       << ", PulsePerSec " << s.pulsesPerSecond;
        }
    };
    Speed read(const std::string& input, std::int64_t hertz, int firstOutput) {
        s.set(input, hertz);
        s.scans(1);
        const std::string unit = "R0.";
        return {s[firstOutput == 0 ? "M0.0" : "M0.1"], s[unit + std::to_string(firstOutput)],
                s[unit + std::to_string(firstOutput + 1)]};
    }
    Speed up(std::int64_t hertz) { return read("IA0.0", hertz, 0); }
    Speed upDown(std::int64_t hertz) { return read("IA0.2", hertz, 2); }

    MachineCodeSetting m_setting;
    Simulated s;
};

// The manual's photocell (Part 1, 9.2): 20 pulses a revolution at 24.4
// revolutions a second.
TEST_P(CounterInputCall, TheManualsPhotocellCounts488PulsesASecond) {
    EXPECT_EQ(up(488), (Speed{1, 5, 488}));
    EXPECT_EQ(up(0), (Speed{1, 0, 0}));
}

TEST_P(CounterInputCall, EdgesPer10msAreTheNearestIntegerAHalfAwayFromZero) {
    EXPECT_EQ(up(449).edgesPer10ms, 4);
    EXPECT_EQ(up(450).edgesPer10ms, 5);
    EXPECT_EQ(up(49).edgesPer10ms, 0);
    EXPECT_EQ(up(50).edgesPer10ms, 1);
    EXPECT_EQ(upDown(-449).edgesPer10ms, -4);
    EXPECT_EQ(upDown(-450).edgesPer10ms, -5);
    EXPECT_EQ(upDown(-50).edgesPer10ms, -1);
}

TEST_P(CounterInputCall, ValidIsTheCountersRangeUpTo14000Hz) {
    EXPECT_EQ(up(14000), (Speed{1, 140, 14000}));
    EXPECT_EQ(up(14001), (Speed{0, 140, 14001}));
    // An up counter counts no pulses below 0 Hz.
    EXPECT_EQ(up(-1), (Speed{0, 0, -1}));
    EXPECT_EQ(upDown(-14000), (Speed{1, -140, -14000}));
    EXPECT_EQ(upDown(-14001), (Speed{0, -140, -14001}));
    EXPECT_EQ(upDown(14001).valid, 0);
}

TEST_P(CounterInputCall, TheDirectionIsTheSignAndOnlyInputAIsRead) {
    EXPECT_EQ(upDown(300), (Speed{1, 3, 300}));
    EXPECT_EQ(upDown(-300), (Speed{1, -3, -300}));
    s.set("IA0.3", 5000);
    s.scans(1);
    EXPECT_EQ(s["R0.3"], -300);
}

TEST_P(CounterInputCall, ASpeedBeyondARegisterSaturates) {
    EXPECT_EQ(up(INT_MAX), (Speed{0, 32767, 32767}));
    EXPECT_EQ(upDown(INT_MIN), (Speed{0, -32768, -32768}));
    EXPECT_EQ(up(3276800).edgesPer10ms, 32767);
}

INSTANTIATE_TEST_SUITE_P(EveryTier, CounterInputCall, rs::test::kEveryTier, rs::test::tierName);

} // namespace
