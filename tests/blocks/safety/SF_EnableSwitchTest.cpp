// SPDX-License-Identifier: GPL-3.0-or-later
#include "SafetyBench.h"

#include <gtest/gtest.h>

// SF_EnableSwitch of Rungsmith_Safety walked through every state and
// transition of the state machine in docs/safety-blocks.md (the public model's,
// with C040's static reset as its C020's). Ch1 off and Ch2 on is the release
// position, both on the enable position, anything else the panic position.
// DiagCodes read as signed registers: 16#8000 -32768, 16#8004 -32764,
// 16#8005 -32763, 16#8006 -32762, 16#8007 -32761, 16#C001 -16383,
// 16#C002 -16382, 16#C010 -16368, 16#C020 -16352, 16#C030 -16336,
// 16#C040 -16320.

using rs::safetytest::holdsOnBothInstructionSets;

namespace {

::testing::AssertionResult switchHolds(const std::string& bindings, const std::string& scenario) {
    const std::string names = "! I0.0=Act\n! I0.1=Safety\n! I0.2=Ch1\n! I0.3=Ch2\n"
                              "! I0.4=ResetButton\n! I0.5=AutoReset\n! M0.0=Ready\n! M0.1=Out\n"
                              "! M0.2=Error\n! R0.0=DiagCode\n";
    const std::string record = ";@block SF_EnableSwitch S_SafetyActive=\"Safety\" "
                               "S_EnableSwitchCh1=\"Ch1\" S_EnableSwitchCh2=\"Ch2\" "
                               "Ready=\"Ready\" S_EnableSwitchOut=\"Out\" Error=\"Error\" "
                               "DiagCode=\"DiagCode\" " +
                               bindings + "\n;@end\n";
    return holdsOnBothInstructionSets(names, record, scenario);
}

const std::string kEnableSwitchReset = "Reset=\"ResetButton\"";

// From activation to 8006: the switch released, the safety function active.
const std::string kToReleased = R"(
set Ch2 1
set Safety 1
scans 1
expect DiagCode -32764
scans 1
expect DiagCode -32763
scans 1
expect DiagCode -32762
)";

// From 8006 to 8000: the enable position.
const std::string kToSwitchEnabled = kToReleased + R"(
set Ch1 1
scans 1
expect DiagCode -32768
expect Out 1
)";

// From 8000 through the panic position to C030, enable again.
const std::string kToPanicEnable = kToSwitchEnabled + R"(
set Ch1 0
set Ch2 0
scans 1
expect DiagCode -32761
set Ch1 1
set Ch2 1
scans 1
expect DiagCode -16336
)";

} // namespace

TEST(SF_EnableSwitch, ActivateOffHoldsStateZeroWithEveryOutputOff) {
    EXPECT_TRUE(switchHolds(kEnableSwitchReset + " Activate=\"Act\"", R"(
set Safety 1
set Ch2 1
scans 2
expect DiagCode 0
expect Ready 0
expect Out 0
expect Error 0
set Act 1
scans 1
# the first active scan: 0000 -> 8004
expect DiagCode -32764
expect Ready 1
expect Out 0
scans 2
set Ch1 1
scans 1
expect DiagCode -32768
expect Out 1
set Act 0
scans 1
expect DiagCode 0
expect Ready 0
expect Out 0
# Activate off also leaves an error state
set Act 1
scans 3
expect DiagCode -16368
expect Error 1
set Act 0
scans 1
expect DiagCode 0
expect Error 0
)"));
}

TEST(SF_EnableSwitch, OpenInputsMeanActiveAndNoReset) {
    EXPECT_TRUE(switchHolds("", R"(
set Ch1 1
set Ch2 1
scans 1
expect DiagCode -32764
expect Ready 1
expect Out 0
run 1s
expect DiagCode -32764
expect Out 0
)"));
}

TEST(SF_EnableSwitch, TheSafetyFunctionOffIs8004FromEveryState) {
    EXPECT_TRUE(switchHolds(kEnableSwitchReset, kToSwitchEnabled + R"(
set Safety 0
scans 1
expect DiagCode -32764
expect Out 0
expect Ready 1
scans 3
expect DiagCode -32764
set Safety 1
scans 1
expect DiagCode -32763
scans 1
# the enable position when it starts again is not released: C010
expect DiagCode -16368
set Safety 0
scans 1
expect DiagCode -32764
expect Error 0
)"));
    EXPECT_TRUE(switchHolds(kEnableSwitchReset, kToPanicEnable + R"(
set Safety 0
scans 1
expect DiagCode -32764
)"));
}

TEST(SF_EnableSwitch, TheEnablePositionFromTheReleasePositionSwitchesOn) {
    EXPECT_TRUE(switchHolds(kEnableSwitchReset, kToReleased + R"(
expect Out 0
expect Error 0
scans 5
expect DiagCode -32762
set Ch1 1
scans 1
expect DiagCode -32768
expect Out 1
expect Error 0
scans 5
expect DiagCode -32768
set Ch1 0
scans 1
expect DiagCode -32762
expect Out 0
set Ch1 1
scans 1
expect DiagCode -32768
)"));
}

TEST(SF_EnableSwitch, ThePanicPositionSwitchesOffAndTheReleasePositionLeavesIt) {
    // from 8000: neither channel, or Ch1 only
    EXPECT_TRUE(switchHolds(kEnableSwitchReset, kToSwitchEnabled + R"(
set Ch1 0
set Ch2 0
scans 1
expect DiagCode -32761
expect Out 0
expect Error 0
scans 3
expect DiagCode -32761
set Ch2 1
scans 1
expect DiagCode -32762
)"));
    EXPECT_TRUE(switchHolds(kEnableSwitchReset, kToSwitchEnabled + R"(
set Ch2 0
scans 1
expect DiagCode -32761
)"));
    // from 8006: neither channel, or Ch1 only
    EXPECT_TRUE(switchHolds(kEnableSwitchReset, kToReleased + R"(
set Ch2 0
scans 1
expect DiagCode -32761
)"));
    EXPECT_TRUE(switchHolds(kEnableSwitchReset, kToReleased + R"(
set Ch1 1
set Ch2 0
scans 1
expect DiagCode -32761
)"));
}

TEST(SF_EnableSwitch, TheEnablePositionFromPanicIsC030AndLeavingItC040) {
    EXPECT_TRUE(switchHolds(kEnableSwitchReset, kToPanicEnable + R"(
expect Error 1
expect Out 0
scans 3
expect DiagCode -16336
set Ch1 0
scans 1
expect DiagCode -16320
expect Error 1
set Ch1 1
scans 1
expect DiagCode -16336
set Ch1 0
set Ch2 0
scans 1
expect DiagCode -16320
scans 3
expect DiagCode -16320
set ResetButton 1
scans 1
expect DiagCode -32761
expect Error 0
set Ch2 1
scans 1
expect DiagCode -32762
)"));
}

TEST(SF_EnableSwitch, AResetHeldWhenC040IsReachedIsC002LeftByReleasingIt) {
    EXPECT_TRUE(switchHolds(kEnableSwitchReset, kToPanicEnable + R"(
set ResetButton 1
scans 1
expect DiagCode -16336
set Ch1 0
scans 1
expect DiagCode -16320
scans 1
expect DiagCode -16382
expect Error 1
scans 3
expect DiagCode -16382
set ResetButton 0
scans 1
expect DiagCode -16320
set ResetButton 1
scans 1
expect DiagCode -32761
)"));
    // the enable position again comes before the static reset
    EXPECT_TRUE(switchHolds(kEnableSwitchReset, kToPanicEnable + R"(
set ResetButton 1
set Ch1 0
scans 1
expect DiagCode -16320
set Ch1 1
scans 1
expect DiagCode -16336
)"));
}

TEST(SF_EnableSwitch, NotReleasedWhenTheSafetyFunctionStartsIsC010) {
    EXPECT_TRUE(switchHolds(kEnableSwitchReset, R"(
set Safety 1
scans 2
expect DiagCode -32763
scans 1
expect DiagCode -16368
expect Error 1
)"));
    EXPECT_TRUE(switchHolds(kEnableSwitchReset, R"(
set Safety 1
set Ch1 1
scans 3
expect DiagCode -16368
)"));
    EXPECT_TRUE(switchHolds(kEnableSwitchReset, R"(
set Safety 1
set Ch1 1
set Ch2 1
scans 3
expect DiagCode -16368
expect Out 0
)"));
}

TEST(SF_EnableSwitch, C010IsLeftByTheReleasePositionAndAPressOfReset) {
    EXPECT_TRUE(switchHolds(kEnableSwitchReset, R"(
set Safety 1
scans 3
expect DiagCode -16368
set Ch2 1
scans 1
expect DiagCode -16352
expect Error 1
set Ch2 0
scans 1
expect DiagCode -16368
set Ch2 1
scans 1
expect DiagCode -16352
scans 3
expect DiagCode -16352
set ResetButton 1
scans 1
expect DiagCode -32762
expect Error 0
)"));
}

TEST(SF_EnableSwitch, AResetHeldInC020IsC001LeftByReleasingIt) {
    EXPECT_TRUE(switchHolds(kEnableSwitchReset, R"(
set Safety 1
set ResetButton 1
scans 3
expect DiagCode -16368
set Ch2 1
scans 1
expect DiagCode -16352
scans 1
expect DiagCode -16383
expect Error 1
scans 3
expect DiagCode -16383
set ResetButton 0
scans 1
expect DiagCode -16352
set ResetButton 1
scans 1
expect DiagCode -32762
)"));
    // leaving the release position comes before the static reset
    EXPECT_TRUE(switchHolds(kEnableSwitchReset, R"(
set Safety 1
set ResetButton 1
scans 3
set Ch2 1
scans 1
expect DiagCode -16352
set Ch1 1
scans 1
expect DiagCode -16368
)"));
}

TEST(SF_EnableSwitch, AutoResetLeavesC020AndC040WithoutAPress) {
    EXPECT_TRUE(switchHolds(kEnableSwitchReset + " S_AutoReset=\"AutoReset\"", R"(
set AutoReset 1
set ResetButton 1
set Safety 1
scans 3
expect DiagCode -16368
set Ch2 1
scans 1
expect DiagCode -16352
scans 1
expect DiagCode -32762
expect Error 0
)"));
    EXPECT_TRUE(switchHolds(kEnableSwitchReset + " S_AutoReset=\"AutoReset\"", kToPanicEnable + R"(
set AutoReset 1
set ResetButton 1
set Ch1 0
scans 1
expect DiagCode -16320
scans 1
expect DiagCode -32761
)"));
}
