// SPDX-License-Identifier: GPL-3.0-or-later
#include "SafetyBench.h"

#include <gtest/gtest.h>

// SF_SafetyRequest of Rungsmith_Safety walked through every state and
// transition of the PLCopen state machine (docs/safety-blocks.md). OpMode on
// is operation mode, off the request for the safe state; Ack is the
// actuator's acknowledgement. DiagCodes read as signed registers:
// 16#8000 -32768, 16#8001 -32767, 16#8002 -32766, 16#8003 -32765,
// 16#8005 -32763, 16#8012 -32750, 16#C002 -16382, 16#C003 -16381,
// 16#C004 -16380, 16#C005 -16379.

using rs::safetytest::holdsOnBothInstructionSets;

namespace {

// A unit with one instance whose inputs, outputs and DiagCode are bound;
// `bindings` adds further pins (MonitoringTime among them: open it is 0).
::testing::AssertionResult requestHolds(const std::string& bindings, const std::string& scenario) {
    const std::string names = "! I0.0=Act\n! I0.1=OpMode\n! I0.2=Ack\n! I0.3=ResetButton\n"
                              "! M0.0=Ready\n! M0.1=Active\n! M0.2=Request\n! M0.3=Error\n"
                              "! R0.0=DiagCode\n! R0.1=Limit\n";
    const std::string record =
        ";@block SF_SafetyRequest S_OpMode=\"OpMode\" S_Acknowledge=\"Ack\" Ready=\"Ready\" "
        "S_SafetyActive=\"Active\" S_SafetyRequest=\"Request\" Error=\"Error\" "
        "DiagCode=\"DiagCode\" " +
        bindings + "\n;@end\n";
    return holdsOnBothInstructionSets(names, record, scenario);
}

const std::string kRequestTime = "MonitoringTime=\"0s05\" ";
const std::string kRequestReset = kRequestTime + "Reset=\"ResetButton\"";

// From activation to 8002: a press of Reset without the acknowledgement, in
// operation mode.
const std::string kToOperation = R"(
set OpMode 1
scans 1
set ResetButton 1
scans 1
expect DiagCode -32766
set ResetButton 0
)";

} // namespace

TEST(SF_SafetyRequest, ActivateOffHoldsStateZeroWithEveryOutputOff) {
    EXPECT_TRUE(requestHolds(kRequestReset + " Activate=\"Act\"", R"(
set OpMode 1
set Ack 1
scans 2
expect DiagCode 0
expect Ready 0
expect Active 0
expect Request 0
expect Error 0
set Act 1
scans 1
# the first active scan: 0000 -> 8001
expect DiagCode -32767
expect Ready 1
expect Request 0
set ResetButton 1
scans 1
expect DiagCode -32750
expect Request 1
set Act 0
scans 1
expect DiagCode 0
expect Ready 0
expect Request 0
# Activate off also leaves an error state
set Act 1
scans 1
set ResetButton 0
scans 1
set ResetButton 1
scans 1
expect DiagCode -32750
set OpMode 0
scans 2
expect DiagCode -32768
expect Active 1
set Ack 0
scans 1
expect DiagCode -16382
expect Error 1
set Act 0
scans 1
expect DiagCode 0
expect Error 0
expect Ready 0
)"));
}

TEST(SF_SafetyRequest, OpenInputsMeanActiveAndNeverAPress) {
    EXPECT_TRUE(requestHolds(kRequestTime, R"(
set OpMode 1
set Ack 1
scans 1
expect DiagCode -32767
expect Ready 1
expect Active 0
expect Request 0
expect Error 0
run 1s
expect DiagCode -32767
)"));
}

TEST(SF_SafetyRequest, APressWithoutTheAcknowledgementIsOperationModeAndItComingOrGoingSwaps) {
    EXPECT_TRUE(requestHolds(kRequestReset, kToOperation + R"(
expect Request 1
expect Active 0
expect Error 0
scans 3
expect DiagCode -32766
set Ack 1
scans 1
expect DiagCode -32750
expect Request 1
scans 3
expect DiagCode -32750
set Ack 0
scans 1
expect DiagCode -32766
expect Request 1
)"));
}

TEST(SF_SafetyRequest, APressWithTheAcknowledgementIsOperationModeAcknowledged) {
    EXPECT_TRUE(requestHolds(kRequestReset, R"(
set OpMode 1
set Ack 1
scans 1
set ResetButton 1
scans 1
expect DiagCode -32750
expect Request 1
expect Active 0
)"));
}

TEST(SF_SafetyRequest, AReleaseHeldFromTheStartIsNoPress) {
    EXPECT_TRUE(requestHolds(kRequestReset, R"(
set ResetButton 1
set OpMode 1
scans 5
expect DiagCode -32767
set ResetButton 0
scans 1
set ResetButton 1
scans 1
expect DiagCode -32766
)"));
}

TEST(SF_SafetyRequest, TheAcknowledgementExactlyMonitoringTimeAfterTheRequestIsSafe) {
    EXPECT_TRUE(requestHolds(kRequestReset, kToOperation + R"(
set OpMode 0
scans 1
# 8002 -> 8003: the request drops S_SafetyRequest
expect DiagCode -32765
expect Request 0
expect Active 0
expect Error 0
run 40ms
expect DiagCode -32765
set Ack 1
# the acknowledgement is seen 50 ms after the request
scans 1
expect DiagCode -32768
expect Active 1
expect Request 0
expect Error 0
scans 3
expect DiagCode -32768
)"));
}

TEST(SF_SafetyRequest, TheAcknowledgementOneScanLateIsErrorC003UntilAPress) {
    EXPECT_TRUE(requestHolds(kRequestReset, kToOperation + R"(
set OpMode 0
scans 1
run 50ms
expect DiagCode -32765
# the timer comes first in 8003's list
set Ack 1
set OpMode 1
scans 1
expect DiagCode -16381
expect Error 1
expect Active 0
expect Request 0
expect Ready 1
scans 3
expect DiagCode -16381
set ResetButton 1
scans 1
expect DiagCode -32763
expect Error 0
expect Request 0
)"));
}

TEST(SF_SafetyRequest, AResetHeldInC003IsC005UntilReleased) {
    EXPECT_TRUE(requestHolds(kRequestReset, kToOperation + R"(
set OpMode 0
set ResetButton 1
scans 1
run 60ms
expect DiagCode -16381
scans 1
expect DiagCode -16379
expect Error 1
set ResetButton 0
scans 1
expect DiagCode -16381
set ResetButton 1
scans 1
expect DiagCode -32763
)"));
}

TEST(SF_SafetyRequest, AfterAnErrorOperationModeLeadsOnAgain) {
    EXPECT_TRUE(requestHolds(kRequestReset, kToOperation + R"(
set OpMode 0
scans 1
run 60ms
set ResetButton 1
scans 1
expect DiagCode -32763
set ResetButton 0
scans 3
expect DiagCode -32763
set OpMode 1
set Ack 1
scans 1
expect DiagCode -32750
expect Request 1
)"));
}

TEST(SF_SafetyRequest, OperationModeBackBeforeTheAcknowledgementIsOperationModeAgain) {
    EXPECT_TRUE(requestHolds(kRequestReset, kToOperation + R"(
set OpMode 0
scans 1
expect DiagCode -32765
run 40ms
# S_OpMode comes before S_Acknowledge in 8003's list
set OpMode 1
set Ack 1
scans 1
expect DiagCode -32750
expect Request 1
run 1s
expect DiagCode -32750
# 8012 -> 8003, left in the next scan with the acknowledgement still on
set OpMode 0
scans 1
expect DiagCode -32765
expect Request 0
scans 1
expect DiagCode -32768
)"));
}

TEST(SF_SafetyRequest, TheMonitoringTimeRunsAfreshOnEachRequest) {
    EXPECT_TRUE(requestHolds(kRequestReset, kToOperation + R"(
set OpMode 0
scans 1
run 40ms
set OpMode 1
scans 1
expect DiagCode -32750
scans 1
expect DiagCode -32766
run 1s
set OpMode 0
scans 1
expect DiagCode -32765
run 50ms
expect DiagCode -32765
scans 1
expect DiagCode -16381
)"));
}

TEST(SF_SafetyRequest, LosingTheAcknowledgementInTheSafeStateIsErrorC002UntilAPress) {
    EXPECT_TRUE(requestHolds(kRequestReset, kToOperation + R"(
set OpMode 0
scans 1
set Ack 1
scans 1
expect DiagCode -32768
# not S_Acknowledge comes before S_OpMode in 8000's list
set Ack 0
set OpMode 1
scans 1
expect DiagCode -16382
expect Error 1
expect Active 0
expect Request 0
scans 3
expect DiagCode -16382
set ResetButton 1
scans 1
expect DiagCode -32763
expect Error 0
set OpMode 0
scans 1
set ResetButton 0
set OpMode 1
scans 1
expect DiagCode -32750
)"));
}

TEST(SF_SafetyRequest, AResetHeldInC002IsC004UntilReleased) {
    EXPECT_TRUE(requestHolds(kRequestReset, kToOperation + R"(
set OpMode 0
scans 1
set Ack 1
scans 1
set ResetButton 1
scans 1
expect DiagCode -32768
set Ack 0
scans 1
expect DiagCode -16382
scans 1
expect DiagCode -16380
expect Error 1
expect Active 0
set ResetButton 0
scans 1
expect DiagCode -16382
set ResetButton 1
scans 1
expect DiagCode -32763
)"));
}

TEST(SF_SafetyRequest, OperationModeLeavesTheSafeState) {
    EXPECT_TRUE(requestHolds(kRequestReset, kToOperation + R"(
set OpMode 0
scans 1
set Ack 1
scans 1
expect Active 1
set OpMode 1
scans 1
expect DiagCode -32750
expect Active 0
expect Request 1
)"));
}

TEST(SF_SafetyRequest, AMonitoringTimeInARegisterOfZeroFailsEveryRequest) {
    EXPECT_TRUE(requestHolds("MonitoringTime=\"Limit\" Reset=\"ResetButton\"", kToOperation + R"(
set Limit 0
set OpMode 0
scans 1
expect DiagCode -32765
set Ack 1
scans 1
expect DiagCode -16381
set Limit 3
set ResetButton 1
scans 1
set OpMode 1
scans 1
set Ack 0
scans 1
expect DiagCode -32766
set OpMode 0
scans 1
run 20ms
set Ack 1
scans 1
expect DiagCode -32768
)"));
}
