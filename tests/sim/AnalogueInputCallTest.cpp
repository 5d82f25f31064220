// SPDX-License-Identifier: GPL-3.0-or-later
// ReadVoltage, ReadCurrent and their _32 forms as the simulator runs them
// (docs/image-format.md, "System instructions"), in each of its tiers: the
// machine code, the unmarked interpreter and the marking interpreter.
#include "SimulationFixture.h"
#include "SimulatorTier.h"

#include <gtest/gtest.h>

#include <climits>
#include <ostream>
#include <string>

using rs::test::MachineCodeSetting;
using rs::test::Simulated;
using rs::test::SimulatorTier;
using namespace rs;

namespace {

// A D45 reading each of its four instructions from an input of its own.
const char* kAnalogueProgram =
    "! id_pluto_Double:00=000000000000\n"
    "! type_pluto:00=D45,is3\n"
    "! pgm_pluto:00\n"
    "! IA0.0,voltage\n"
    "! IA0.1,current\n"
    "! IA0.2,current\n"
    "! IA0.3,voltage\n"
    "S0.0_0\n"
    "(DR0.20 = 1000000)\n"
    ";@system ReadVoltage Input=\"IA0.0\" Value_0V=\"-50\" Value_10V=\"150\" Q=\"M0.0\" "
    "Voltage=\"R0.0\" Scaled_Value=\"R0.1\"\n"
    ";@system ReadCurrent Input=\"IA0.1\" Value_4mA=\"R0.10\" Value_20mA=\"488\" Q=\"M0.1\" "
    "Current=\"R0.2\" Scaled_Value=\"R0.3\"\n"
    ";@system ReadCurrent_32 Input=\"IA0.2\" Value_4mA=\"0\" Value_20mA=\"DR0.20\" Q=\"M0.2\" "
    "Current=\"DR0.4\" Scaled_Value=\"DR0.6\"\n"
    ";@system ReadVoltage_32 Input=\"IA0.3\" Value_0V=\"-2147483648\" Value_10V=\"2147483647\" "
    "Q=\"M0.3\" Voltage=\"DR0.8\" Scaled_Value=\"DR0.12\"\n";

class AnalogueInputCall : public testing::TestWithParam<SimulatorTier> {
protected:
    AnalogueInputCall() : m_setting(GetParam() == SimulatorTier::MachineCode), s(kAnalogueProgram) {
        s.simulation->unit(0)->setEagerConduction(GetParam() == SimulatorTier::MarkingInterpreter);
    }

    // Q, the calibrated value and the scaled value after a scan with `input`.
    struct Reading {
        std::int64_t q, value, scaled;
        friend bool operator==(const Reading&, const Reading&) = default;
        friend std::ostream& operator<<(std::ostream& out, const Reading& r) {
            return out << "Q " << r.q << ", value " << r.value << ", scaled " << r.scaled;
        }
    };
    Reading read(const std::string& input, std::int64_t value, const std::string& q,
                 const std::string& calibrated, const std::string& scaled) {
        s.set(input, value);
        s.scans(1);
        return {s[q], s[calibrated], s[scaled]};
    }
    Reading voltage(std::int64_t mV) { return read("IA0.0", mV, "M0.0", "R0.0", "R0.1"); }
    Reading current(std::int64_t uA) { return read("IA0.1", uA, "M0.1", "R0.2", "R0.3"); }
    Reading current32(std::int64_t uA) { return read("IA0.2", uA, "M0.2", "DR0.4", "DR0.6"); }
    Reading voltage32(std::int64_t mV) { return read("IA0.3", mV, "M0.3", "DR0.8", "DR0.12"); }

    MachineCodeSetting m_setting;
    Simulated s;
};

// The manual's example (Part 1, 9.2): 4 mA is 0, 20 mA is 488, and a wire
// break (0 mA) reads -122.
TEST_P(AnalogueInputCall, ReadCurrentScalesTheManualsExampleAndSeesAWireBreak) {
    EXPECT_EQ(current(4000), (Reading{1, 4000, 0}));
    EXPECT_EQ(current(20000), (Reading{1, 20000, 488}));
    EXPECT_EQ(current(12000), (Reading{1, 12000, 244}));
    EXPECT_EQ(current(0), (Reading{0, 0, -122}));
}

TEST_P(AnalogueInputCall, QIsTheNominalRangeWithItsEnds) {
    EXPECT_EQ(current(3999).q, 0);
    EXPECT_EQ(current(20001).q, 0);
    EXPECT_EQ(voltage(0).q, 1);
    EXPECT_EQ(voltage(10000).q, 1);
    EXPECT_EQ(voltage(-1).q, 0);
    EXPECT_EQ(voltage(10001).q, 0);
}

TEST_P(AnalogueInputCall, TheScaledValueIsTheNearestIntegerAHalfRoundedUp) {
    // -50 at 0 V, 150 at 10 V: 20 per volt.
    EXPECT_EQ(voltage(5000), (Reading{1, 5000, 50}));
    EXPECT_EQ(voltage(2525).scaled, 1);  // 0.5
    EXPECT_EQ(voltage(2475).scaled, 0);  // -0.5
    EXPECT_EQ(voltage(2476).scaled, 0);  // -0.48
    EXPECT_EQ(voltage(2474).scaled, -1); // -0.52
    EXPECT_EQ(voltage(-1000), (Reading{0, -1000, -70}));
}

TEST_P(AnalogueInputCall, TheScaleIsReadInEveryScan) {
    s.set("R0.10", -488);
    EXPECT_EQ(current(12000).scaled, 0);
    s.set("R0.10", 488);
    EXPECT_EQ(current(12000).scaled, 488);
}

TEST_P(AnalogueInputCall, ARegisterOutputSaturates) {
    // 40 mA scales to 1098 and reads 40000 µA, which no register holds.
    EXPECT_EQ(current(40000), (Reading{0, 32767, 1098}));
    EXPECT_EQ(current(-40000), (Reading{0, -32768, -1342}));
    s.set("R0.10", -32768);
    EXPECT_EQ(current(2000000).scaled, 32767);
    EXPECT_EQ(current(-2000000).scaled, -32768);
}

TEST_P(AnalogueInputCall, TheThirtyTwoBitFormsTakeDoubleRegisters) {
    EXPECT_EQ(current32(12000), (Reading{1, 12000, 500000}));
    EXPECT_EQ(current32(0), (Reading{0, 0, -250000}));
    EXPECT_EQ(current32(INT_MAX), (Reading{0, INT_MAX, INT_MAX}));
    EXPECT_EQ(current32(INT_MIN), (Reading{0, INT_MIN, INT_MIN}));
    // The whole 32-bit range over 0-10 V: exact, without overflow.
    EXPECT_EQ(voltage32(0), (Reading{1, 0, INT_MIN}));
    EXPECT_EQ(voltage32(10000), (Reading{1, 10000, INT_MAX}));
    EXPECT_EQ(voltage32(5000).scaled, 0); // -2^31 + (2^32 - 1) / 2 = -0.5, a half up
    EXPECT_EQ(voltage32(INT_MAX).scaled, INT_MAX);
    EXPECT_EQ(voltage32(INT_MIN).scaled, INT_MIN);
}

INSTANTIATE_TEST_SUITE_P(EveryTier, AnalogueInputCall, rs::test::kEveryTier, rs::test::tierName);

} // namespace
