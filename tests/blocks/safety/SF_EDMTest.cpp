// SPDX-License-Identifier: GPL-3.0-or-later
#include "SafetyBench.h"

#include <gtest/gtest.h>

// SF_EDM of Rungsmith_Safety walked through every state and transition of the
// state machine written down in docs/safety-blocks.md (Rungsmith's reading of
// the public descriptions). Control is S_OutControl; Edm1 and Edm2 are the
// feedbacks, on while the actuator is off. MonitoringTime is 0s05 unless a
// test says otherwise. DiagCodes read as signed registers: 16#8000 -32768,
// 16#8401 -31743, 16#8810 -30704, 16#C001 -16383, 16#C010 -16368,
// 16#C020 -16352, 16#C030 -16336, 16#C040 -16320, 16#C050 -16304,
// 16#C060 -16288, 16#C070 -16272, 16#C080 -16256, 16#C090 -16240,
// 16#C100 -16128.

using rs::safetytest::holdsOnBothInstructionSets;

namespace {

::testing::AssertionResult edmHolds(const std::string& bindings, const std::string& scenario) {
    const std::string names = "! I0.0=Act\n! I0.1=Control\n! I0.2=Edm1\n! I0.3=Edm2\n"
                              "! I0.4=ResetButton\n! I0.5=StartReset\n! M0.0=Ready\n! M0.1=Out\n"
                              "! M0.2=Error\n! R0.0=DiagCode\n! R0.1=Limit\n";
    const std::string record = ";@block SF_EDM S_OutControl=\"Control\" S_EDM1=\"Edm1\" "
                               "S_EDM2=\"Edm2\" Ready=\"Ready\" S_EDM_Out=\"Out\" Error=\"Error\" "
                               "DiagCode=\"DiagCode\" " +
                               bindings + "\n;@end\n";
    return holdsOnBothInstructionSets(names, record, scenario);
}

const std::string kEdmTime = "MonitoringTime=\"0s05\" ";
const std::string kEdmReset = kEdmTime + "Reset=\"ResetButton\"";

// From activation to 8810 with both feedbacks in the actuator's initial state.
const std::string kToSwitchedOff = R"(
set Edm1 1
set Edm2 1
scans 1
expect DiagCode -31743
set ResetButton 1
scans 1
expect DiagCode -30704
set ResetButton 0
scans 1
)";

// From 8810 to 8000: the output switched on, the feedbacks still on.
const std::string kToSwitchedOn = kToSwitchedOff + R"(
set Control 1
scans 1
expect DiagCode -32768
expect Out 1
)";

} // namespace

TEST(SF_EDM, ActivateOffHoldsStateZeroWithEveryOutputOff) {
    EXPECT_TRUE(edmHolds(kEdmReset + " Activate=\"Act\"", R"(
set Edm1 1
set Edm2 1
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
expect Error 0
set ResetButton 1
scans 1
set ResetButton 0
set Control 1
scans 1
expect DiagCode -32768
expect Out 1
set Act 0
scans 1
expect DiagCode 0
expect Ready 0
expect Out 0
# Activate off also leaves an error state
set Control 0
set Act 1
scans 1
set ResetButton 1
scans 1
set ResetButton 0
set Edm1 0
set Control 1
scans 1
expect DiagCode -16368
expect Error 1
set Act 0
scans 1
expect DiagCode 0
expect Error 0
expect Ready 0
)"));
}

TEST(SF_EDM, OpenInputsMeanActiveAndNoAcknowledgement) {
    EXPECT_TRUE(edmHolds(kEdmTime, R"(
set Edm1 1
set Edm2 1
set Control 1
scans 1
expect DiagCode -31743
expect Ready 1
expect Out 0
run 1s
expect DiagCode -31743
expect Out 0
)"));
}

TEST(SF_EDM, StartResetAcknowledgesAtStartAndMakesAHeldResetNoError) {
    EXPECT_TRUE(edmHolds(kEdmReset + " S_StartReset=\"StartReset\"", R"(
set StartReset 1
set ResetButton 1
set Edm1 1
set Edm2 1
scans 1
expect DiagCode -31743
scans 1
expect DiagCode -30704
expect Error 0
set Control 1
scans 1
expect DiagCode -32768
)"));
}

TEST(SF_EDM, AResetHeldAtStartIsAStaticResetLeftByReleasingIt) {
    EXPECT_TRUE(edmHolds(kEdmReset, R"(
set ResetButton 1
set Edm1 1
set Edm2 1
scans 1
expect DiagCode -31743
scans 1
expect DiagCode -16383
expect Error 1
expect Ready 1
expect Out 0
scans 3
expect DiagCode -16383
set ResetButton 0
scans 1
expect DiagCode -31743
expect Error 0
set ResetButton 1
scans 1
expect DiagCode -30704
)"));
}

TEST(SF_EDM, AResetPressedWithTheControlsRisingEdgeIsC100LeftByAPressWithTheControlOff) {
    EXPECT_TRUE(edmHolds(kEdmReset, R"(
set Edm1 1
set Edm2 1
scans 1
set ResetButton 1
set Control 1
scans 1
expect DiagCode -16128
expect Error 1
expect Out 0
set ResetButton 0
scans 1
# a press while the control is still on does not leave it
set ResetButton 1
scans 1
expect DiagCode -16128
set ResetButton 0
set Control 0
scans 3
expect DiagCode -16128
set ResetButton 1
scans 1
expect DiagCode -30704
expect Error 0
)"));
}

TEST(SF_EDM, APressWithTheControlAlreadyOnAcknowledgesAndSwitchesOnInTheNextScan) {
    EXPECT_TRUE(edmHolds(kEdmReset, R"(
set Edm1 1
set Edm2 1
set Control 1
scans 2
expect DiagCode -31743
set ResetButton 1
scans 1
expect DiagCode -30704
expect Out 0
scans 1
expect DiagCode -32768
expect Out 1
)"));
}

TEST(SF_EDM, TheOutputFollowsTheControlWhileTheFeedbacksSwitchInTime) {
    EXPECT_TRUE(edmHolds(kEdmReset, kToSwitchedOn + R"(
expect Ready 1
expect Error 0
set Edm1 0
set Edm2 0
scans 20
expect DiagCode -32768
expect Out 1
set Control 0
scans 1
expect DiagCode -30704
expect Out 0
set Edm1 1
set Edm2 1
scans 20
expect DiagCode -30704
set Control 1
scans 1
expect DiagCode -32768
)"));
}

TEST(SF_EDM, SwitchingOnWithAFeedbackNotInItsInitialStateIsC010C020OrC030) {
    EXPECT_TRUE(edmHolds(kEdmReset, kToSwitchedOff + R"(
set Edm1 0
set Control 1
scans 1
expect DiagCode -16368
expect Error 1
expect Out 0
)"));
    EXPECT_TRUE(edmHolds(kEdmReset, kToSwitchedOff + R"(
set Edm2 0
set Control 1
scans 1
expect DiagCode -16352
expect Error 1
)"));
    EXPECT_TRUE(edmHolds(kEdmReset, kToSwitchedOff + R"(
set Edm1 0
set Edm2 0
set Control 1
scans 1
expect DiagCode -16336
expect Error 1
)"));
}

TEST(SF_EDM, AnErrorIsLeftOnlyByAPressOfResetWithTheControlOff) {
    EXPECT_TRUE(edmHolds(kEdmReset, kToSwitchedOff + R"(
set Edm1 0
set Control 1
set ResetButton 1
scans 1
expect DiagCode -16368
# held, not pressed
scans 3
expect DiagCode -16368
set ResetButton 0
scans 1
set ResetButton 1
scans 1
# pressed with the control on
expect DiagCode -16368
set ResetButton 0
set Control 0
scans 1
expect DiagCode -16368
set Edm1 1
set ResetButton 1
scans 1
expect DiagCode -30704
expect Error 0
)"));
}

TEST(SF_EDM, FeedbacksOffExactlyMonitoringTimeAfterSwitchingOnPassAndOneScanLaterFail) {
    // 8000 entered in scan k: a feedback seen off in scan k + 5 passes.
    EXPECT_TRUE(edmHolds(kEdmReset, kToSwitchedOn + R"(
scans 4
set Edm1 0
set Edm2 0
scans 1
expect DiagCode -32768
scans 50
expect DiagCode -32768
expect Error 0
)"));
    EXPECT_TRUE(edmHolds(kEdmReset, kToSwitchedOn + R"(
scans 5
expect DiagCode -32768
scans 1
expect DiagCode -16240
expect Error 1
expect Out 0
)"));
    EXPECT_TRUE(edmHolds(kEdmReset, kToSwitchedOn + R"(
set Edm2 0
scans 5
expect DiagCode -32768
scans 1
expect DiagCode -16272
expect Error 1
)"));
    EXPECT_TRUE(edmHolds(kEdmReset, kToSwitchedOn + R"(
set Edm1 0
scans 5
expect DiagCode -32768
scans 1
expect DiagCode -16256
expect Error 1
)"));
}

TEST(SF_EDM, AFeedbackComingBackWhileSwitchedOnAfterTheTimeIsAnError) {
    EXPECT_TRUE(edmHolds(kEdmReset, kToSwitchedOn + R"(
set Edm1 0
set Edm2 0
scans 10
expect DiagCode -32768
set Edm1 1
scans 1
expect DiagCode -16272
expect Error 1
set Control 0
set ResetButton 1
scans 1
expect DiagCode -30704
)"));
}

TEST(SF_EDM, FeedbacksBackExactlyMonitoringTimeAfterSwitchingOffPassAndOneScanLaterFail) {
    const std::string switchedOffAgain = kToSwitchedOn + R"(
set Edm1 0
set Edm2 0
scans 2
set Control 0
scans 1
expect DiagCode -30704
)";
    // 8810 entered in scan j: feedbacks seen back in scan j + 5 pass.
    EXPECT_TRUE(edmHolds(kEdmReset, switchedOffAgain + R"(
scans 4
set Edm1 1
set Edm2 1
scans 1
expect DiagCode -30704
scans 50
expect DiagCode -30704
expect Error 0
)"));
    EXPECT_TRUE(edmHolds(kEdmReset, switchedOffAgain + R"(
scans 5
expect DiagCode -30704
scans 1
expect DiagCode -16288
expect Error 1
)"));
    EXPECT_TRUE(edmHolds(kEdmReset, switchedOffAgain + R"(
set Edm2 1
scans 5
expect DiagCode -30704
scans 1
expect DiagCode -16320
expect Error 1
)"));
    EXPECT_TRUE(edmHolds(kEdmReset, switchedOffAgain + R"(
set Edm1 1
scans 5
expect DiagCode -30704
scans 1
expect DiagCode -16304
expect Error 1
)"));
}

TEST(SF_EDM, TheMonitoringTimeErrorsTakePrecedenceOverSwitchingOn) {
    EXPECT_TRUE(edmHolds(kEdmReset, R"(
scans 1
expect DiagCode -31743
set ResetButton 1
scans 1
# 8810 entered in scan j, both feedbacks off
expect DiagCode -30704
set ResetButton 0
scans 5
expect DiagCode -30704
set Edm2 1
set Control 1
scans 1
# the time has run out in scan j + 6: C040, not C010
expect DiagCode -16320
)"));
}

TEST(SF_EDM, AMonitoringTimeErrorIsLeftByAPressWithTheControlOff) {
    EXPECT_TRUE(edmHolds(kEdmReset, kToSwitchedOn + R"(
scans 6
expect DiagCode -16240
set Control 0
set ResetButton 1
scans 1
expect DiagCode -30704
set ResetButton 0
scans 5
expect DiagCode -30704
scans 1
expect DiagCode -30704
expect Error 0
)"));
}

TEST(SF_EDM, AMonitoringTimeRegisterHoldingZeroAllowsNoDelay) {
    EXPECT_TRUE(edmHolds("MonitoringTime=\"Limit\" Reset=\"ResetButton\"", kToSwitchedOn + R"(
scans 1
expect DiagCode -16240
)"));
    EXPECT_TRUE(edmHolds("MonitoringTime=\"Limit\" Reset=\"ResetButton\"", R"(
set Limit 3
)" + kToSwitchedOn + R"(
scans 3
expect DiagCode -32768
scans 1
expect DiagCode -16240
)"));
}
