// SPDX-License-Identifier: GPL-3.0-or-later
#include "StopBlockTest.h"

// The state machine of SF_EmergencyStop and SF_ESPE walked through every
// state and transition (docs/safety-blocks.md). SafeIn is the safety input
// (on: no stop requested). DiagCodes read as signed registers: 16#8000
// -32768, 16#8001 -32767, 16#8002 -32766, 16#8003 -32765, 16#8004 -32764,
// 16#8005 -32763, 16#C001 -16383, 16#C002 -16382.

using rs::safetytest::StopBlockTest;

TEST_P(StopBlockTest, ActivateOffHoldsStateZeroWithEveryOutputOff) {
    EXPECT_TRUE(holds("Activate=\"Act\" Reset=\"ResetButton\"", R"(
set SafeIn 1
scans 2
expect DiagCode 0
expect Ready 0
expect Out 0
expect Error 0
set Act 1
scans 1
# the first active scan: 0000 -> 8001
expect DiagCode -32767
expect Ready 1
expect Out 0
scans 1
expect DiagCode -32766
scans 1
expect DiagCode -32765
set ResetButton 1
scans 1
expect DiagCode -32768
expect Out 1
set Act 0
scans 1
expect DiagCode 0
expect Ready 0
expect Out 0
# Activate off also leaves an error state; the button still held is a static reset
set Act 1
scans 3
expect DiagCode -32765
scans 1
expect DiagCode -16383
expect Error 1
set Act 0
scans 1
expect DiagCode 0
expect Error 0
expect Ready 0
)"));
}

TEST_P(StopBlockTest, OpenInputsMeanActiveWithoutStartResetAndNeverAPress) {
    EXPECT_TRUE(holds("", R"(
scans 1
expect DiagCode -32767
expect Ready 1
expect Out 0
expect Error 0
scans 1
expect DiagCode -32766
set SafeIn 1
scans 1
expect DiagCode -32765
run 1s
expect DiagCode -32765
expect Out 0
)"));
}

TEST_P(StopBlockTest, AtStartAReleasedStopAndANewPressEnable) {
    EXPECT_TRUE(holds("Reset=\"ResetButton\"", R"(
scans 2
expect DiagCode -32766
# a press while the stop is requested does nothing
set ResetButton 1
scans 1
expect DiagCode -32766
set ResetButton 0
scans 1
set SafeIn 1
scans 1
expect DiagCode -32765
expect Out 0
expect Error 0
# requested again before the acknowledgement
set SafeIn 0
scans 1
expect DiagCode -32766
set SafeIn 1
scans 1
expect DiagCode -32765
set ResetButton 1
scans 1
expect DiagCode -32768
expect Out 1
expect Ready 1
expect Error 0
)"));
}

TEST_P(StopBlockTest, AResetHeldWhileTheStartAcknowledgementIsAwaitedIsErrorC001UntilReleased) {
    EXPECT_TRUE(holds("Reset=\"ResetButton\"", R"(
scans 2
expect DiagCode -32766
# pressed in the scan the stop is released: 8002 looks at the stop only
set ResetButton 1
set SafeIn 1
scans 1
expect DiagCode -32765
scans 1
expect DiagCode -16383
expect Error 1
expect Out 0
expect Ready 1
# only releasing the button leaves C001, whatever the stop does
set SafeIn 0
scans 5
expect DiagCode -16383
set ResetButton 0
scans 1
expect DiagCode -32765
expect Error 0
scans 1
expect DiagCode -32766
set SafeIn 1
scans 1
set ResetButton 1
scans 1
expect DiagCode -32768
)"));
}

TEST_P(StopBlockTest, WhileTheStartAcknowledgementIsAwaitedAStopComesBeforeAPress) {
    EXPECT_TRUE(holds("Reset=\"ResetButton\"", R"(
set SafeIn 1
scans 3
expect DiagCode -32765
set SafeIn 0
set ResetButton 1
scans 1
expect DiagCode -32766
expect Out 0
)"));
}

TEST_P(StopBlockTest, AfterAStopAReleaseAndANewPressRestart) {
    EXPECT_TRUE(holds("Reset=\"ResetButton\"", R"(
set SafeIn 1
scans 3
set ResetButton 1
scans 1
expect DiagCode -32768
set ResetButton 0
scans 1
set SafeIn 0
scans 1
# 8000 -> 8004: the output drops in the scan the stop is seen
expect DiagCode -32764
expect Out 0
expect Error 0
expect Ready 1
set ResetButton 1
scans 1
expect DiagCode -32764
set ResetButton 0
scans 1
set SafeIn 1
scans 1
expect DiagCode -32763
expect Out 0
# requested again before the acknowledgement
set SafeIn 0
scans 1
expect DiagCode -32764
set SafeIn 1
scans 1
expect DiagCode -32763
scans 5
expect DiagCode -32763
set ResetButton 1
scans 1
expect DiagCode -32768
expect Out 1
)"));
}

TEST_P(StopBlockTest, AResetHeldWhileTheRestartIsAwaitedIsErrorC002UntilReleased) {
    EXPECT_TRUE(holds("Reset=\"ResetButton\"", R"(
set SafeIn 1
scans 3
set ResetButton 1
scans 1
expect DiagCode -32768
# the button stays held through the stop and its release
set SafeIn 0
scans 1
expect DiagCode -32764
set SafeIn 1
scans 1
expect DiagCode -32763
scans 1
expect DiagCode -16382
expect Error 1
expect Out 0
expect Ready 1
set SafeIn 0
scans 2
expect DiagCode -16382
set ResetButton 0
scans 1
expect DiagCode -32763
expect Error 0
scans 1
expect DiagCode -32764
set SafeIn 1
scans 1
set ResetButton 1
scans 1
expect DiagCode -32768
)"));
}

TEST_P(StopBlockTest, WhileTheRestartIsAwaitedAStopComesBeforeAPress) {
    EXPECT_TRUE(holds("Reset=\"ResetButton\"", R"(
set SafeIn 1
scans 3
set ResetButton 1
scans 1
set ResetButton 0
set SafeIn 0
scans 1
set SafeIn 1
scans 1
expect DiagCode -32763
set SafeIn 0
set ResetButton 1
scans 1
expect DiagCode -32764
)"));
}

TEST_P(StopBlockTest, StartResetEnablesAtStartWithoutAPress) {
    EXPECT_TRUE(holds("S_StartReset=\"StartReset\" Reset=\"ResetButton\"", R"(
set StartReset 1
set SafeIn 1
scans 1
expect DiagCode -32767
scans 1
expect DiagCode -32768
expect Out 1
)"));
}

TEST_P(StopBlockTest, StartResetWithTheStopRequestedAwaitsTheRestart) {
    EXPECT_TRUE(holds("S_StartReset=\"StartReset\" Reset=\"ResetButton\"", R"(
set StartReset 1
scans 2
expect DiagCode -32764
set SafeIn 1
scans 1
expect DiagCode -32763
set ResetButton 1
scans 1
expect DiagCode -32768
)"));
}

TEST_P(StopBlockTest, AutoResetRestartsWhenTheStopIsReleased) {
    EXPECT_TRUE(holds("S_StartReset=\"StartReset\" S_AutoReset=\"AutoReset\"", R"(
set StartReset 1
set AutoReset 1
set SafeIn 1
scans 2
expect DiagCode -32768
set SafeIn 0
scans 1
expect DiagCode -32764
expect Out 0
set SafeIn 1
scans 1
expect DiagCode -32768
expect Out 1
# while a restart is awaited, AutoReset coming on restarts
set AutoReset 0
set SafeIn 0
scans 1
set SafeIn 1
scans 1
expect DiagCode -32763
set AutoReset 1
scans 1
expect DiagCode -32768
)"));
}
