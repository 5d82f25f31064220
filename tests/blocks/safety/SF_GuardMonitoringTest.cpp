// SPDX-License-Identifier: GPL-3.0-or-later
#include "SafetyBench.h"

#include <gtest/gtest.h>

// SF_GuardMonitoring of Rungsmith_Safety walked through every state and
// transition of the PLCopen state machine (docs/safety-blocks.md). Switch1
// and Switch2 are the guard's switches (on: closed). DiagCodes read as signed
// registers: 16#8000 -32768, 16#8001 -32767, 16#8002 -32766, 16#8003 -32765,
// 16#8004 -32764, 16#8005 -32763, 16#8012 -32750, 16#8014 -32748,
// 16#C001 -16383, 16#C011 -16367, 16#C012 -16366.

using rs::safetytest::holdsOnBothInstructionSets;

namespace {

// A unit with one instance whose switches, outputs and DiagCode are bound;
// `bindings` adds further pins (DiscrepancyTime among them: open it is 0).
::testing::AssertionResult guardHolds(const std::string& bindings, const std::string& scenario) {
    const std::string names = "! I0.0=Act\n! I0.1=Switch1\n! I0.2=Switch2\n! I0.3=StartReset\n"
                              "! I0.4=AutoReset\n! I0.5=ResetButton\n! M0.0=Ready\n! M0.1=Out\n"
                              "! M0.2=Error\n! R0.0=DiagCode\n! R0.1=Limit\n";
    const std::string record =
        ";@block SF_GuardMonitoring S_GuardSwitch1=\"Switch1\" S_GuardSwitch2=\"Switch2\" "
        "Ready=\"Ready\" S_GuardMonitoring=\"Out\" Error=\"Error\" DiagCode=\"DiagCode\" " +
        bindings + "\n;@end\n";
    return holdsOnBothInstructionSets(names, record, scenario);
}

const std::string kGuardTime = "DiscrepancyTime=\"0s05\" ";
const std::string kGuardReset = kGuardTime + "Reset=\"ResetButton\"";

} // namespace

TEST(SF_GuardMonitoring, ActivateOffHoldsStateZeroWithEveryOutputOff) {
    EXPECT_TRUE(guardHolds(kGuardReset + " Activate=\"Act\" S_StartReset=\"StartReset\"", R"(
set Switch1 1
set Switch2 1
set StartReset 1
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
expect DiagCode -32768
expect Out 1
set Act 0
scans 1
expect DiagCode 0
expect Ready 0
expect Out 0
# Activate off also leaves an error state
set Act 1
set Switch1 0
set Switch2 0
scans 3
expect DiagCode -32750
set Switch1 1
scans 1
run 60ms
expect DiagCode -16367
expect Error 1
set Act 0
scans 1
expect DiagCode 0
expect Error 0
expect Ready 0
)"));
}

TEST(SF_GuardMonitoring, OpenInputsMeanActiveWithoutStartResetAndNeverAPress) {
    EXPECT_TRUE(guardHolds(kGuardTime, R"(
set Switch1 1
set Switch2 1
scans 1
expect DiagCode -32767
expect Ready 1
expect Out 0
expect Error 0
scans 1
expect DiagCode -32765
run 1s
expect DiagCode -32765
expect Out 0
)"));
}

TEST(SF_GuardMonitoring, AGuardClosedAtStartNeedsAPressAndMustThenOpenFully) {
    EXPECT_TRUE(guardHolds(kGuardReset, R"(
set Switch1 1
set Switch2 1
scans 2
expect DiagCode -32765
expect Out 0
expect Error 0
set ResetButton 1
scans 1
expect DiagCode -32768
expect Out 1
expect Ready 1
expect Error 0
set ResetButton 0
# a closed guard stays enabled
scans 3
expect DiagCode -32768
expect Out 1
# 8000 -> 8002: the output drops in the scan one switch opens
set Switch2 0
scans 1
expect DiagCode -32766
expect Out 0
# only a full opening leads on: closing again does nothing
set Switch2 1
scans 3
expect DiagCode -32766
expect Out 0
)"));
}

TEST(SF_GuardMonitoring, StartResetEnablesAGuardClosedAtStartWithoutAPress) {
    EXPECT_TRUE(guardHolds(kGuardReset + " S_StartReset=\"StartReset\"", R"(
set StartReset 1
set Switch1 1
set Switch2 1
scans 1
expect DiagCode -32767
scans 1
expect DiagCode -32768
expect Out 1
)"));
}

TEST(SF_GuardMonitoring, StartResetWithTheGuardOpenAwaitsAFullOpening) {
    EXPECT_TRUE(guardHolds(kGuardReset + " S_StartReset=\"StartReset\"", R"(
set StartReset 1
set Switch1 1
scans 2
expect DiagCode -32766
expect Out 0
)"));
}

TEST(SF_GuardMonitoring, AGuardOpenedFullyAndClosedInTimeAwaitsAPress) {
    EXPECT_TRUE(guardHolds(kGuardReset, R"(
set Switch1 1
scans 2
expect DiagCode -32766
# one switch still closed: not yet fully open
scans 3
expect DiagCode -32766
set Switch1 0
scans 1
expect DiagCode -32750
expect Out 0
expect Error 0
expect Ready 1
run 1s
expect DiagCode -32750
set Switch1 1
scans 1
expect DiagCode -32764
expect Out 0
expect Error 0
run 40ms
expect DiagCode -32764
set Switch2 1
# Switch2 is seen 50 ms after Switch1
scans 1
expect DiagCode -32763
expect Out 0
expect Error 0
scans 1
expect DiagCode -32765
expect Out 0
set ResetButton 1
scans 1
expect DiagCode -32768
expect Out 1
)"));
}

TEST(SF_GuardMonitoring, Switch2OneScanLateIsErrorC011UntilBothAreOpen) {
    EXPECT_TRUE(guardHolds(kGuardReset, R"(
scans 3
expect DiagCode -32750
set Switch1 1
scans 1
run 50ms
expect DiagCode -32764
set Switch2 1
# Switch2 would be seen 60 ms after Switch1: the timer is first in 8004's list
scans 1
expect DiagCode -16367
expect Error 1
expect Out 0
expect Ready 1
set Switch1 0
scans 3
expect DiagCode -16367
set Switch1 1
set Switch2 0
scans 2
expect DiagCode -16367
set Switch1 0
scans 1
expect DiagCode -32750
expect Error 0
)"));
}

TEST(SF_GuardMonitoring, Switch1FollowingSwitch2ExactlyDiscrepancyTimeLaterPasses) {
    EXPECT_TRUE(guardHolds(kGuardReset, R"(
scans 3
set Switch2 1
scans 1
expect DiagCode -32748
expect Out 0
expect Error 0
run 40ms
expect DiagCode -32748
set Switch1 1
scans 1
expect DiagCode -32763
)"));
}

TEST(SF_GuardMonitoring, Switch1OneScanLateIsErrorC012UntilBothAreOpen) {
    EXPECT_TRUE(guardHolds(kGuardReset, R"(
scans 3
set Switch2 1
scans 1
run 50ms
expect DiagCode -32748
# the timer comes before Switch2 opening again
set Switch2 0
scans 1
expect DiagCode -16366
expect Error 1
expect Out 0
set Switch1 1
scans 1
expect DiagCode -16366
set Switch1 0
scans 1
expect DiagCode -32750
expect Error 0
)"));
}

TEST(SF_GuardMonitoring, AFirstSwitchOpeningAgainAwaitsAFullOpeningAndStopsTheTimer) {
    EXPECT_TRUE(guardHolds(kGuardReset, R"(
scans 3
set Switch1 1
scans 1
run 40ms
expect DiagCode -32764
set Switch1 0
scans 1
expect DiagCode -32766
scans 1
expect DiagCode -32750
run 100ms
expect DiagCode -32750
expect Error 0
# entering 8004 again times afresh: 50 ms more pass, 60 ms do not
set Switch1 1
scans 1
expect DiagCode -32764
run 50ms
expect DiagCode -32764
# the timer comes before Switch1 opening again
set Switch1 0
scans 1
expect DiagCode -16367
)"));
}

TEST(SF_GuardMonitoring, Switch2OpeningAgainAwaitsAFullOpening) {
    EXPECT_TRUE(guardHolds(kGuardReset, R"(
scans 3
set Switch2 1
scans 1
run 40ms
expect DiagCode -32748
set Switch2 0
scans 1
expect DiagCode -32766
run 100ms
expect DiagCode -32750
)"));
}

TEST(SF_GuardMonitoring, BothSwitchesClosingInOneScanPassThroughWaitingForSwitch2) {
    EXPECT_TRUE(guardHolds(kGuardReset, R"(
scans 3
set Switch1 1
set Switch2 1
scans 1
expect DiagCode -32764
scans 1
expect DiagCode -32763
)"));
}

TEST(SF_GuardMonitoring, ASwitchOpeningBeforeTheAcknowledgementAwaitsAFullOpening) {
    EXPECT_TRUE(guardHolds(kGuardReset + " S_AutoReset=\"AutoReset\"", R"(
set AutoReset 1
scans 3
set Switch1 1
set Switch2 1
scans 2
expect DiagCode -32763
# opening comes before S_AutoReset in 8005's list
set Switch1 0
scans 1
expect DiagCode -32766
expect Out 0
)"));
}

TEST(SF_GuardMonitoring, AutoResetAcknowledgesAClosingButNotTheStart) {
    EXPECT_TRUE(guardHolds(kGuardReset + " S_AutoReset=\"AutoReset\"", R"(
set AutoReset 1
set Switch1 1
set Switch2 1
scans 2
expect DiagCode -32765
expect Out 0
# 8003 -> 8002 on opening
set Switch1 0
set Switch2 0
scans 1
expect DiagCode -32766
scans 1
expect DiagCode -32750
set Switch1 1
set Switch2 1
scans 2
expect DiagCode -32763
scans 1
expect DiagCode -32768
expect Out 1
set Switch1 0
scans 1
expect DiagCode -32766
expect Out 0
)"));
}

TEST(SF_GuardMonitoring, AResetHeldWhileAPressIsAwaitedIsErrorC001UntilReleased) {
    EXPECT_TRUE(guardHolds(kGuardReset, R"(
set ResetButton 1
scans 3
expect DiagCode -32750
set Switch1 1
set Switch2 1
scans 3
expect DiagCode -32765
scans 1
expect DiagCode -16383
expect Error 1
expect Out 0
expect Ready 1
# only releasing the button leaves C001, whatever the guard does
set Switch1 0
scans 3
expect DiagCode -16383
set ResetButton 0
scans 1
expect DiagCode -32765
expect Error 0
scans 1
expect DiagCode -32766
)"));
}

TEST(SF_GuardMonitoring, AHeldResetComesBeforeAnOpeningAndAnOpeningBeforeAPress) {
    EXPECT_TRUE(guardHolds(kGuardReset, R"(
set ResetButton 1
set Switch1 1
set Switch2 1
scans 2
expect DiagCode -32765
set Switch1 0
scans 1
expect DiagCode -16383
set Switch1 1
set ResetButton 0
scans 1
expect DiagCode -32765
set ResetButton 1
set Switch2 0
scans 1
expect DiagCode -32766
expect Out 0
)"));
}

TEST(SF_GuardMonitoring, ADiscrepancyTimeInARegisterOfZeroFailsEveryClosing) {
    EXPECT_TRUE(guardHolds("DiscrepancyTime=\"Limit\"", R"(
set Limit 0
scans 3
expect DiagCode -32750
set Switch1 1
set Switch2 1
scans 1
expect DiagCode -32764
scans 1
expect DiagCode -16367
set Limit 3
set Switch1 0
set Switch2 0
scans 1
expect DiagCode -32750
set Switch2 1
scans 1
expect DiagCode -32748
run 20ms
set Switch1 1
scans 1
expect DiagCode -32763
)"));
}
