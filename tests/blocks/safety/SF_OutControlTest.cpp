// SPDX-License-Identifier: GPL-3.0-or-later
#include "SafetyBench.h"

#include <gtest/gtest.h>

// SF_OutControl of Rungsmith_Safety walked through every state and
// transition of the state machine written down in docs/safety-blocks.md
// (Rungsmith's reading of the public descriptions). Safe is S_SafeControl,
// Process ProcessControl. DiagCodes read as signed registers: 16#8000 -32768,
// 16#8006 -32762, 16#8401 -31743, 16#8404 -31740, 16#8802 -30718,
// 16#C001 -16383, 16#C010 -16368, 16#C011 -16367, 16#C020 -16352,
// 16#C030 -16336.

using rs::safetytest::holdsOnBothInstructionSets;

namespace {

::testing::AssertionResult outControlHolds(const std::string& bindings,
                                           const std::string& scenario) {
    const std::string names = "! I0.0=Act\n! I0.1=Safe\n! I0.2=Process\n! I0.3=Static\n"
                              "! I0.4=ResetButton\n! I0.5=StartReset\n! I0.6=AutoReset\n"
                              "! M0.0=Ready\n! M0.1=Out\n! M0.2=Error\n! R0.0=DiagCode\n";
    const std::string record = ";@block SF_OutControl S_SafeControl=\"Safe\" "
                               "ProcessControl=\"Process\" Ready=\"Ready\" S_OutControl=\"Out\" "
                               "Error=\"Error\" DiagCode=\"DiagCode\" " +
                               bindings + "\n;@end\n";
    return holdsOnBothInstructionSets(names, record, scenario);
}

const std::string kOutControlReset = "Reset=\"ResetButton\"";

// From activation to 8006 with the safety permission given.
const std::string kToDisabled = R"(
set Safe 1
scans 1
expect DiagCode -31743
set ResetButton 1
scans 1
expect DiagCode -32762
set ResetButton 0
scans 1
)";

// From 8006 to 8000 by a rising edge of ProcessControl.
const std::string kToOutputEnabled = kToDisabled + R"(
set Process 1
scans 1
expect DiagCode -32768
expect Out 1
)";

// From 8000 through a safety demand to 8404.
const std::string kToLocked = kToOutputEnabled + R"(
set Safe 0
scans 1
expect DiagCode -30718
set Process 0
scans 1
set Safe 1
scans 1
expect DiagCode -31740
)";

} // namespace

TEST(SF_OutControl, ActivateOffHoldsStateZeroWithEveryOutputOff) {
    EXPECT_TRUE(outControlHolds(kOutControlReset + " Activate=\"Act\"", R"(
set Safe 1
scans 2
expect DiagCode 0
expect Ready 0
expect Out 0
expect Error 0
set Act 1
scans 1
# the first active scan: 0000 -> 8401
expect DiagCode -31743
expect Ready 1
expect Out 0
set ResetButton 1
scans 1
set ResetButton 0
set Process 1
scans 1
expect DiagCode -32768
expect Out 1
set Act 0
scans 1
expect DiagCode 0
expect Ready 0
expect Out 0
# Activate off also leaves an error state
set Process 0
set Act 1
scans 1
set ResetButton 1
set Process 1
scans 1
expect DiagCode -16352
expect Error 1
set Act 0
scans 1
expect DiagCode 0
expect Error 0
)"));
}

TEST(SF_OutControl, OpenInputsMeanActiveAndNoAcknowledgement) {
    EXPECT_TRUE(outControlHolds("", R"(
set Safe 1
set Process 1
scans 1
expect DiagCode -31743
expect Ready 1
expect Out 0
expect Error 0
run 1s
expect DiagCode -31743
)"));
}

TEST(SF_OutControl, APressAtStartAcknowledgesOnlyWithTheSafetyPermission) {
    EXPECT_TRUE(outControlHolds(kOutControlReset, R"(
scans 1
set ResetButton 1
scans 1
expect DiagCode -31743
set ResetButton 0
set Safe 1
scans 3
expect DiagCode -31743
set ResetButton 1
scans 1
expect DiagCode -32762
expect Out 0
expect Error 0
)"));
}

TEST(SF_OutControl, StartResetAcknowledgesOnceTheSafetyPermissionComes) {
    EXPECT_TRUE(outControlHolds(kOutControlReset + " S_StartReset=\"StartReset\"", R"(
set StartReset 1
set ResetButton 1
scans 5
expect DiagCode -31743
expect Error 0
set Safe 1
scans 1
expect DiagCode -32762
)"));
}

TEST(SF_OutControl, AResetHeldAtStartIsC001LeftByReleasingIt) {
    EXPECT_TRUE(outControlHolds(kOutControlReset, R"(
set ResetButton 1
set Safe 1
scans 1
expect DiagCode -31743
scans 1
expect DiagCode -16383
expect Error 1
expect Ready 1
scans 3
expect DiagCode -16383
set ResetButton 0
scans 1
expect DiagCode -31743
expect Error 0
set ResetButton 1
scans 1
expect DiagCode -32762
)"));
}

TEST(SF_OutControl, ResetAndProcessControlRisingTogetherAtStartIsC020LeftWithBothReleased) {
    EXPECT_TRUE(outControlHolds(kOutControlReset, R"(
set Safe 1
scans 1
set ResetButton 1
set Process 1
scans 1
expect DiagCode -16352
expect Error 1
expect Out 0
set ResetButton 0
scans 2
expect DiagCode -16352
set ResetButton 1
set Process 0
scans 2
expect DiagCode -16352
set ResetButton 0
scans 1
expect DiagCode -31743
expect Error 0
)"));
}

TEST(SF_OutControl, TheOutputFollowsARisingProcessControlWhileSafe) {
    EXPECT_TRUE(outControlHolds(kOutControlReset, kToDisabled + R"(
expect Out 0
scans 5
expect DiagCode -32762
set Process 1
scans 1
expect DiagCode -32768
expect Out 1
expect Ready 1
expect Error 0
scans 5
expect DiagCode -32768
set Process 0
scans 1
expect DiagCode -32762
expect Out 0
set Process 1
scans 1
expect DiagCode -32768
)"));
}

TEST(SF_OutControl, ProcessControlHeldThroughTheAcknowledgementIsC010LeftByReleasingIt) {
    EXPECT_TRUE(outControlHolds(kOutControlReset, R"(
set Safe 1
set Process 1
scans 1
set ResetButton 1
scans 1
expect DiagCode -32762
scans 1
expect DiagCode -16368
expect Error 1
expect Out 0
scans 3
expect DiagCode -16368
set Process 0
scans 1
expect DiagCode -32762
expect Error 0
set Process 1
scans 1
expect DiagCode -32768
)"));
}

TEST(SF_OutControl, StaticControlTakesProcessControlAsALevel) {
    EXPECT_TRUE(outControlHolds(kOutControlReset + " StaticControl=\"Static\"", R"(
set Static 1
set Safe 1
set Process 1
scans 1
set ResetButton 1
scans 1
expect DiagCode -32762
scans 1
expect DiagCode -32768
expect Error 0
set Safe 0
scans 1
expect DiagCode -30718
set Safe 1
scans 1
expect DiagCode -31740
set ResetButton 0
scans 1
set ResetButton 1
scans 1
expect DiagCode -32762
scans 1
expect DiagCode -32768
)"));
}

TEST(SF_OutControl, ASafetyDemandSwitchesOffAndNeedsAPressAndANewProcessEdge) {
    EXPECT_TRUE(outControlHolds(kOutControlReset, kToOutputEnabled + R"(
set Safe 0
scans 1
expect DiagCode -30718
expect Out 0
expect Error 0
scans 5
expect DiagCode -30718
set Safe 1
scans 1
expect DiagCode -31740
expect Out 0
scans 5
expect DiagCode -31740
set ResetButton 1
scans 1
expect DiagCode -32762
scans 1
# ProcessControl still on from before the demand
expect DiagCode -16368
)"));
}

TEST(SF_OutControl, TheSafetyDemandComesBeforeProcessControl) {
    EXPECT_TRUE(outControlHolds(kOutControlReset, kToOutputEnabled + R"(
set Safe 0
set Process 0
scans 1
expect DiagCode -30718
)"));
    EXPECT_TRUE(outControlHolds(kOutControlReset, kToDisabled + R"(
set Safe 0
set Process 1
scans 1
expect DiagCode -30718
expect Out 0
)"));
}

TEST(SF_OutControl, AutoResetRestartsAfterADemandWithoutAPress) {
    EXPECT_TRUE(outControlHolds(kOutControlReset + " S_AutoReset=\"AutoReset\"", R"(
set AutoReset 1
)" + kToOutputEnabled + R"(
set Safe 0
scans 1
expect DiagCode -30718
set Process 0
set Safe 1
scans 1
expect DiagCode -32762
set Process 1
scans 1
expect DiagCode -32768
)"));
    // S_AutoReset switched on while 8404 waits acknowledges there.
    EXPECT_TRUE(outControlHolds(kOutControlReset + " S_AutoReset=\"AutoReset\"", kToLocked + R"(
scans 2
expect DiagCode -31740
set AutoReset 1
scans 1
expect DiagCode -32762
)"));
}

TEST(SF_OutControl, TheSafetyPermissionLostWhileWaitingForThePressIsADemandAgain) {
    EXPECT_TRUE(outControlHolds(kOutControlReset, kToLocked + R"(
set Safe 0
scans 1
expect DiagCode -30718
set Safe 1
scans 1
expect DiagCode -31740
)"));
}

TEST(SF_OutControl, AResetHeldWhen8404IsReachedIsC011LeftByReleasingIt) {
    EXPECT_TRUE(outControlHolds(kOutControlReset, kToOutputEnabled + R"(
set Safe 0
set Process 0
set ResetButton 1
scans 1
expect DiagCode -30718
set Safe 1
scans 1
expect DiagCode -31740
# the static reset comes before the lost permission
set Safe 0
scans 1
expect DiagCode -16367
expect Error 1
scans 3
expect DiagCode -16367
set Safe 1
set ResetButton 0
scans 1
expect DiagCode -31740
expect Error 0
set ResetButton 1
scans 1
expect DiagCode -32762
)"));
    EXPECT_TRUE(outControlHolds(kOutControlReset, kToLocked + R"(
set ResetButton 1
set Safe 0
scans 1
expect DiagCode -30718
)"));
}

TEST(SF_OutControl, ResetAndProcessControlRisingTogetherIn8404IsC030LeftWithBothReleased) {
    EXPECT_TRUE(outControlHolds(kOutControlReset, kToLocked + R"(
set ResetButton 1
set Process 1
scans 1
expect DiagCode -16336
expect Error 1
set ResetButton 0
scans 2
expect DiagCode -16336
set ResetButton 1
set Process 0
scans 2
expect DiagCode -16336
set ResetButton 0
scans 1
expect DiagCode -31740
expect Error 0
)"));
}
