// SPDX-License-Identifier: GPL-3.0-or-later
#include "SafetyBench.h"

#include <gtest/gtest.h>

// SF_Antivalent of Rungsmith_Safety walked through every state and transition
// of the PLCopen state machine (docs/safety-blocks.md). The run position is
// NC on and NO off; the safe position NC off and NO on. DiagCodes read as
// signed registers: 16#8000 -32768, 16#8001 -32767, 16#8004 -32764,
// 16#8005 -32763, 16#8014 -32748, 16#C001 -16383, 16#C002 -16382,
// 16#C003 -16381.

using rs::safetytest::holdsOnBothInstructionSets;

namespace {

const std::string kAntivalentNames =
    "! I0.0=Act\n! I0.1=ChannelNC\n! I0.2=ChannelNO\n! M0.0=Ready\n"
    "! M0.1=Out\n! M0.2=Error\n! R0.0=DiagCode\n! R0.1=Limit\n";

// DiscrepancyTime 0s05 (50 ms); Activate open (on).
const std::string kAntivalentBlock =
    ";@block SF_Antivalent S_ChannelNC=\"ChannelNC\" S_ChannelNO=\"ChannelNO\" "
    "DiscrepancyTime=\"0s05\" Ready=\"Ready\" S_AntivalentOut=\"Out\" Error=\"Error\" "
    "DiagCode=\"DiagCode\"\n;@end\n";

const std::string kActivatedAntivalent =
    ";@block SF_Antivalent Activate=\"Act\" S_ChannelNC=\"ChannelNC\" S_ChannelNO=\"ChannelNO\" "
    "DiscrepancyTime=\"0s05\" Ready=\"Ready\" S_AntivalentOut=\"Out\" Error=\"Error\" "
    "DiagCode=\"DiagCode\"\n;@end\n";

const std::string kAntivalentRegisterTime =
    ";@block SF_Antivalent S_ChannelNC=\"ChannelNC\" S_ChannelNO=\"ChannelNO\" "
    "DiscrepancyTime=\"Limit\" S_AntivalentOut=\"Out\" Error=\"Error\" "
    "DiagCode=\"DiagCode\"\n;@end\n";

} // namespace

TEST(SF_Antivalent, ActivateOffHoldsStateZeroWithEveryOutputOff) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kAntivalentNames, kActivatedAntivalent, R"(
set ChannelNC 1
scans 3
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
set ChannelNO 1
scans 2
expect DiagCode -32764
run 60ms
expect DiagCode -16383
expect Error 1
set Act 0
scans 1
expect DiagCode 0
expect Error 0
expect Ready 0
)"));
}

TEST(SF_Antivalent, AnOpenActivateIsOnFromTheFirstScan) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kAntivalentNames, kAntivalentBlock, R"(
set ChannelNO 1
scans 1
expect DiagCode -32767
expect Ready 1
expect Out 0
expect Error 0
scans 5
expect DiagCode -32767
)"));
}

TEST(SF_Antivalent, BothChannelsTogetherEnableAndTheSafePositionPasses8005) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kAntivalentNames, kAntivalentBlock, R"(
set ChannelNO 1
scans 1
set ChannelNC 1
set ChannelNO 0
scans 1
expect DiagCode -32768
expect Out 1
expect Ready 1
expect Error 0
set ChannelNC 0
set ChannelNO 1
scans 1
# the public model leaves 8000 for 8005 first: its second condition is never taken
expect DiagCode -32763
expect Out 0
expect Error 0
scans 1
expect DiagCode -32767
expect Error 0
)"));
}

TEST(SF_Antivalent, NoFollowingNcExactlyDiscrepancyTimeLaterEnables) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kAntivalentNames, kAntivalentBlock, R"(
set ChannelNO 1
scans 1
set ChannelNC 1
scans 1
expect DiagCode -32764
expect Out 0
expect Error 0
run 40ms
expect DiagCode -32764
set ChannelNO 0
scans 1
expect DiagCode -32768
expect Out 1
)"));
}

TEST(SF_Antivalent, NoOneScanLateIsErrorC001UntilTheSafePosition) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kAntivalentNames, kAntivalentBlock, R"(
set ChannelNO 1
scans 1
set ChannelNC 1
scans 1
run 50ms
expect DiagCode -32764
set ChannelNO 0
scans 1
expect DiagCode -16383
expect Error 1
expect Out 0
expect Ready 1
scans 3
expect DiagCode -16383
set ChannelNC 0
scans 3
expect DiagCode -16383
set ChannelNO 1
scans 1
expect DiagCode -32767
expect Error 0
)"));
}

TEST(SF_Antivalent, NcDroppingBackWaitsAgainAndStopsTheTimer) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kAntivalentNames, kAntivalentBlock, R"(
set ChannelNO 1
scans 1
set ChannelNC 1
scans 1
run 40ms
expect DiagCode -32764
set ChannelNC 0
scans 1
expect DiagCode -32767
run 100ms
expect DiagCode -32767
expect Error 0
set ChannelNC 1
scans 1
expect DiagCode -32764
run 50ms
expect DiagCode -32764
scans 1
expect DiagCode -16383
)"));
}

TEST(SF_Antivalent, NcFollowingNoExactlyDiscrepancyTimeLaterEnables) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kAntivalentNames, kAntivalentBlock, R"(
set ChannelNO 1
scans 1
set ChannelNO 0
scans 1
expect DiagCode -32748
expect Out 0
expect Error 0
run 40ms
expect DiagCode -32748
set ChannelNC 1
scans 1
expect DiagCode -32768
expect Out 1
)"));
}

TEST(SF_Antivalent, NcOneScanLateIsErrorC002UntilTheSafePosition) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kAntivalentNames, kAntivalentBlock, R"(
set ChannelNO 1
scans 1
set ChannelNO 0
scans 1
run 50ms
expect DiagCode -32748
scans 1
expect DiagCode -16382
expect Error 1
expect Out 0
set ChannelNC 1
scans 2
expect DiagCode -16382
set ChannelNC 0
set ChannelNO 1
scans 1
expect DiagCode -32767
expect Error 0
)"));
}

TEST(SF_Antivalent, NoComingBackWaitsAgain) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kAntivalentNames, kAntivalentBlock, R"(
set ChannelNO 1
scans 1
set ChannelNO 0
scans 1
expect DiagCode -32748
run 40ms
expect DiagCode -32748
set ChannelNO 1
scans 1
expect DiagCode -32767
run 100ms
expect DiagCode -32767
)"));
}

TEST(SF_Antivalent, NcOffFollowedExactlyDiscrepancyTimeLaterWaitsAgain) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kAntivalentNames, kAntivalentBlock, R"(
set ChannelNC 1
scans 2
expect Out 1
set ChannelNC 0
scans 1
expect DiagCode -32763
expect Out 0
expect Error 0
run 40ms
expect DiagCode -32763
set ChannelNO 1
scans 1
expect DiagCode -32767
expect Error 0
)"));
}

TEST(SF_Antivalent, NoOnNotFollowedIsErrorC003UntilTheSafePosition) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kAntivalentNames, kAntivalentBlock, R"(
set ChannelNC 1
scans 2
set ChannelNO 1
scans 1
expect DiagCode -32763
# the channel coming back does not enable again
set ChannelNO 0
run 50ms
expect DiagCode -32763
expect Out 0
scans 1
expect DiagCode -16381
expect Error 1
expect Out 0
set ChannelNO 1
scans 2
expect DiagCode -16381
set ChannelNC 0
scans 1
expect DiagCode -32767
expect Error 0
)"));
}

TEST(SF_Antivalent, WithNoDiscrepancyTimeEvenASimultaneousSwitchOffIsErrorC003) {
    // The public model's 8000 always passes 8005, whose timer of 0 has
    // elapsed in the next scan.
    EXPECT_TRUE(holdsOnBothInstructionSets(kAntivalentNames, kAntivalentRegisterTime, R"(
set Limit 0
set ChannelNO 1
scans 1
set ChannelNC 1
set ChannelNO 0
scans 1
expect DiagCode -32768
set ChannelNC 0
set ChannelNO 1
scans 1
expect DiagCode -32763
scans 1
expect DiagCode -16381
set Limit 3
scans 1
expect DiagCode -32767
set ChannelNO 0
scans 1
expect DiagCode -32748
run 20ms
set ChannelNC 1
scans 1
expect DiagCode -32768
)"));
}
