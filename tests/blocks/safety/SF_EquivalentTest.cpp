// SPDX-License-Identifier: GPL-3.0-or-later
#include "SafetyBench.h"

#include <gtest/gtest.h>

// SF_Equivalent of Rungsmith_Safety walked through every state and transition
// of the PLCopen state machine (docs/safety-blocks.md). DiagCodes read as
// signed registers: 16#8000 -32768, 16#8001 -32767, 16#8004 -32764,
// 16#8005 -32763, 16#8014 -32748, 16#C001 -16383, 16#C002 -16382,
// 16#C003 -16381.

using rs::safetytest::holdsOnBothInstructionSets;

namespace {

const std::string kEquivalentNames = "! I0.0=Act\n! I0.1=ChannelA\n! I0.2=ChannelB\n! M0.0=Ready\n"
                                     "! M0.1=Out\n! M0.2=Error\n! R0.0=DiagCode\n! R0.1=Limit\n";

// DiscrepancyTime 0s05 (50 ms); Activate open (on).
const std::string kEquivalentBlock =
    ";@block SF_Equivalent S_ChannelA=\"ChannelA\" S_ChannelB=\"ChannelB\" "
    "DiscrepancyTime=\"0s05\" Ready=\"Ready\" S_EquivalentOut=\"Out\" Error=\"Error\" "
    "DiagCode=\"DiagCode\"\n;@end\n";

const std::string kActivatedEquivalent =
    ";@block SF_Equivalent Activate=\"Act\" S_ChannelA=\"ChannelA\" S_ChannelB=\"ChannelB\" "
    "DiscrepancyTime=\"0s05\" Ready=\"Ready\" S_EquivalentOut=\"Out\" Error=\"Error\" "
    "DiagCode=\"DiagCode\"\n;@end\n";

const std::string kEquivalentRegisterTime =
    ";@block SF_Equivalent S_ChannelA=\"ChannelA\" S_ChannelB=\"ChannelB\" "
    "DiscrepancyTime=\"Limit\" S_EquivalentOut=\"Out\" Error=\"Error\" "
    "DiagCode=\"DiagCode\"\n;@end\n";

// DiscrepancyTime open: blocks.md's default, the time 0.
const std::string kOpenTimeBlock =
    ";@block SF_Equivalent S_ChannelA=\"ChannelA\" S_ChannelB=\"ChannelB\" "
    "S_EquivalentOut=\"Out\" Error=\"Error\" DiagCode=\"DiagCode\"\n;@end\n";

} // namespace

TEST(SF_Equivalent, ActivateOffHoldsStateZeroWithEveryOutputOff) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kEquivalentNames, kActivatedEquivalent, R"(
set ChannelA 1
set ChannelB 1
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
set ChannelB 0
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

TEST(SF_Equivalent, AnOpenActivateIsOnFromTheFirstScan) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kEquivalentNames, kEquivalentBlock, R"(
scans 1
expect DiagCode -32767
expect Ready 1
expect Out 0
expect Error 0
scans 5
expect DiagCode -32767
)"));
}

TEST(SF_Equivalent, BothChannelsTogetherEnableAndBothOffWaitAgain) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kEquivalentNames, kEquivalentBlock, R"(
scans 1
set ChannelA 1
set ChannelB 1
scans 1
expect DiagCode -32768
expect Out 1
expect Ready 1
expect Error 0
set ChannelA 0
set ChannelB 0
scans 1
expect DiagCode -32767
expect Out 0
expect Error 0
)"));
}

TEST(SF_Equivalent, ChannelBFollowingAExactlyDiscrepancyTimeLaterEnables) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kEquivalentNames, kEquivalentBlock, R"(
scans 1
set ChannelA 1
scans 1
expect DiagCode -32764
expect Out 0
expect Error 0
run 40ms
expect DiagCode -32764
set ChannelB 1
# B is seen 50 ms after A
scans 1
expect DiagCode -32768
expect Out 1
)"));
}

TEST(SF_Equivalent, ChannelBOneScanLateIsErrorC001UntilBothAreOff) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kEquivalentNames, kEquivalentBlock, R"(
scans 1
set ChannelA 1
scans 1
run 50ms
expect DiagCode -32764
set ChannelB 1
# B would be seen 60 ms after A: the timer is first in 8004's list
scans 1
expect DiagCode -16383
expect Error 1
expect Out 0
expect Ready 1
set ChannelA 0
scans 3
expect DiagCode -16383
set ChannelA 1
set ChannelB 0
scans 3
expect DiagCode -16383
set ChannelA 0
scans 1
expect DiagCode -32767
expect Error 0
)"));
}

TEST(SF_Equivalent, ChannelADroppingBackWaitsAgainAndStopsTheTimer) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kEquivalentNames, kEquivalentBlock, R"(
scans 1
set ChannelA 1
scans 1
run 40ms
expect DiagCode -32764
set ChannelA 0
scans 1
expect DiagCode -32767
run 100ms
expect DiagCode -32767
expect Error 0
# entering 8004 again times afresh: 50 ms more pass, 60 ms do not
set ChannelA 1
scans 1
expect DiagCode -32764
run 50ms
expect DiagCode -32764
scans 1
expect DiagCode -16383
)"));
}

TEST(SF_Equivalent, InWaitingForBTheFirstTrueConditionWins) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kEquivalentNames, kEquivalentBlock, R"(
scans 1
set ChannelA 1
scans 1
# not A comes before B in 8004's list: 8001, then 8014 from there
set ChannelA 0
set ChannelB 1
scans 1
expect DiagCode -32767
scans 1
expect DiagCode -32748
set ChannelB 0
scans 1
set ChannelA 1
scans 1
expect DiagCode -32764
run 50ms
# the timer comes before not A
set ChannelA 0
scans 1
expect DiagCode -16383
)"));
}

TEST(SF_Equivalent, ChannelAFollowingBExactlyDiscrepancyTimeLaterEnables) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kEquivalentNames, kEquivalentBlock, R"(
scans 1
set ChannelB 1
scans 1
expect DiagCode -32748
expect Out 0
expect Error 0
run 40ms
expect DiagCode -32748
set ChannelA 1
scans 1
expect DiagCode -32768
expect Out 1
)"));
}

TEST(SF_Equivalent, ChannelAOneScanLateIsErrorC002UntilBothAreOff) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kEquivalentNames, kEquivalentBlock, R"(
scans 1
set ChannelB 1
scans 1
run 50ms
expect DiagCode -32748
scans 1
expect DiagCode -16382
expect Error 1
expect Out 0
set ChannelA 1
scans 1
expect DiagCode -16382
set ChannelB 0
scans 2
expect DiagCode -16382
set ChannelA 0
scans 1
expect DiagCode -32767
expect Error 0
)"));
}

TEST(SF_Equivalent, ChannelBDroppingBackWaitsAgain) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kEquivalentNames, kEquivalentBlock, R"(
scans 1
set ChannelB 1
scans 1
run 40ms
expect DiagCode -32748
set ChannelB 0
scans 1
expect DiagCode -32767
run 100ms
expect DiagCode -32767
)"));
}

TEST(SF_Equivalent, OneChannelOffFollowedExactlyDiscrepancyTimeLaterWaitsAgain) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kEquivalentNames, kEquivalentBlock, R"(
scans 1
set ChannelA 1
set ChannelB 1
scans 1
expect Out 1
set ChannelA 0
scans 1
# 8000 -> 8005: the output drops in the scan the change is seen
expect DiagCode -32763
expect Out 0
expect Error 0
run 40ms
expect DiagCode -32763
set ChannelB 0
scans 1
expect DiagCode -32767
expect Error 0
)"));
}

TEST(SF_Equivalent, OneChannelOffNotFollowedIsErrorC003UntilBothAreOff) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kEquivalentNames, kEquivalentBlock, R"(
scans 1
set ChannelA 1
set ChannelB 1
scans 1
set ChannelB 0
scans 1
expect DiagCode -32763
# the channel coming back does not enable again
set ChannelB 1
run 50ms
expect DiagCode -32763
expect Out 0
scans 1
expect DiagCode -16381
expect Error 1
expect Out 0
set ChannelA 0
scans 2
expect DiagCode -16381
set ChannelB 0
scans 1
expect DiagCode -32767
expect Error 0
)"));
}

TEST(SF_Equivalent, ADiscrepancyTimeInARegisterOfZeroWantsBothInOneScan) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kEquivalentNames, kEquivalentRegisterTime, R"(
set Limit 0
scans 1
set ChannelA 1
set ChannelB 1
scans 1
expect DiagCode -32768
set ChannelA 0
set ChannelB 0
scans 1
expect DiagCode -32767
set ChannelA 1
scans 1
expect DiagCode -32764
set ChannelB 1
scans 1
expect DiagCode -16383
set Limit 3
set ChannelA 0
set ChannelB 0
scans 1
set ChannelB 1
scans 1
expect DiagCode -32748
run 20ms
set ChannelA 1
scans 1
expect DiagCode -32768
)"));
}

TEST(SF_Equivalent, AnOpenDiscrepancyTimeIsZeroAndWantsBothInOneScan) {
    EXPECT_TRUE(holdsOnBothInstructionSets(kEquivalentNames, kOpenTimeBlock, R"(
scans 1
set ChannelA 1
set ChannelB 1
scans 1
expect DiagCode -32768
expect Out 1
set ChannelA 0
set ChannelB 0
scans 1
expect DiagCode -32767
set ChannelA 1
scans 1
expect DiagCode -32764
set ChannelB 1
# B seen one scan after A: the timer of 0 has elapsed
scans 1
expect DiagCode -16383
expect Error 1
expect Out 0
set ChannelA 0
set ChannelB 0
scans 1
set ChannelB 1
scans 1
expect DiagCode -32748
set ChannelA 1
scans 1
expect DiagCode -16382
expect Error 1
)"));
}
