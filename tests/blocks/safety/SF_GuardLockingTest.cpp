// SPDX-License-Identifier: GPL-3.0-or-later
#include "SafetyBench.h"

#include <gtest/gtest.h>

// SF_GuardLocking of Rungsmith_Safety walked through every state and
// transition of the PLCopen state machine (docs/safety-blocks.md). Closed is
// S_GuardMonitoring, Locked S_GuardLock, Safe S_SafetyActive, Unlock the
// UnlockRequest. DiagCodes read as signed registers: 16#8000 -32768,
// 16#8001 -32767, 16#8003 -32765, 16#8011 -32751, 16#8012 -32750,
// 16#8013 -32749, 16#8014 -32748, 16#C001 -16383, 16#C002 -16382,
// 16#C003 -16381, 16#C004 -16380.

using rs::safetytest::holdsOnBothInstructionSets;

namespace {

// A unit with one instance whose required inputs, outputs and DiagCode are
// bound; `bindings` adds further pins.
::testing::AssertionResult lockingHolds(const std::string& bindings, const std::string& scenario) {
    const std::string names = "! I0.0=Act\n! I0.1=Closed\n! I0.2=Locked\n! I0.3=Safe\n"
                              "! I0.4=Unlock\n! I0.5=StartReset\n! I0.6=AutoReset\n"
                              "! I0.7=ResetButton\n! M0.0=Ready\n! M0.1=GuardLocked\n"
                              "! M0.2=UnlockGuard\n! M0.3=Error\n! R0.0=DiagCode\n";
    const std::string record =
        ";@block SF_GuardLocking S_GuardMonitoring=\"Closed\" S_GuardLock=\"Locked\" "
        "S_SafetyActive=\"Safe\" Ready=\"Ready\" S_GuardLocked=\"GuardLocked\" "
        "S_UnlockGuard=\"UnlockGuard\" Error=\"Error\" DiagCode=\"DiagCode\" " +
        bindings + "\n;@end\n";
    return holdsOnBothInstructionSets(names, record, scenario);
}

const std::string kLockingPress = "Reset=\"ResetButton\" UnlockRequest=\"Unlock\"";

// Closed, locked and acknowledged at start with a press, the hazard safe.
const std::string kLocked = R"(
set Closed 1
set Locked 1
set Safe 1
scans 1
set ResetButton 1
scans 1
expect DiagCode -32768
set ResetButton 0
)";

} // namespace

TEST(SF_GuardLocking, ActivateOffHoldsStateZeroWithEveryOutputOff) {
    EXPECT_TRUE(lockingHolds(kLockingPress + " Activate=\"Act\" S_StartReset=\"StartReset\"", R"(
set Closed 1
set Locked 1
set Safe 1
set StartReset 1
scans 2
expect DiagCode 0
expect Ready 0
expect GuardLocked 0
expect UnlockGuard 0
expect Error 0
set Act 1
scans 1
# the first active scan: 0000 -> 8001
expect DiagCode -32767
expect Ready 1
expect GuardLocked 0
scans 1
expect DiagCode -32768
expect GuardLocked 1
set Act 0
scans 1
expect DiagCode 0
expect Ready 0
expect GuardLocked 0
# Activate off also leaves an error state
set Act 1
scans 2
set Locked 0
scans 1
expect DiagCode -16380
expect Error 1
set Act 0
scans 1
expect DiagCode 0
expect Error 0
expect Ready 0
)"));
}

TEST(SF_GuardLocking, OpenInputsMeanActiveWithoutStartResetAndNeverAPress) {
    EXPECT_TRUE(lockingHolds("", R"(
set Closed 1
set Locked 1
set Safe 1
scans 1
expect DiagCode -32767
expect Ready 1
expect GuardLocked 0
expect UnlockGuard 0
expect Error 0
run 1s
expect DiagCode -32767
)"));
}

TEST(SF_GuardLocking, AGuardClosedAndLockedAtStartNeedsAPress) {
    EXPECT_TRUE(lockingHolds(kLockingPress, kLocked + R"(
expect GuardLocked 1
expect UnlockGuard 0
expect Error 0
scans 3
expect DiagCode -32768
expect GuardLocked 1
)"));
}

TEST(SF_GuardLocking, StartResetLocksAtStartWithoutAPressEvenWithResetHeld) {
    EXPECT_TRUE(lockingHolds(kLockingPress + " S_StartReset=\"StartReset\"", R"(
set StartReset 1
set ResetButton 1
set Closed 1
set Locked 1
scans 2
expect DiagCode -32768
expect GuardLocked 1
)"));
}

TEST(SF_GuardLocking, AResetHeldAtStartIsErrorC001UntilReleasedBeforeAnOpenGuard) {
    EXPECT_TRUE(lockingHolds(kLockingPress, R"(
set ResetButton 1
scans 2
expect DiagCode -16383
expect Error 1
expect Ready 1
set Closed 1
set Locked 1
scans 2
expect DiagCode -16383
set ResetButton 0
scans 1
expect DiagCode -32767
expect Error 0
scans 2
expect DiagCode -32767
set ResetButton 1
scans 1
expect DiagCode -32768
)"));
}

TEST(SF_GuardLocking, AGuardUnlockedAtStartWaitsForClosedAndLockedThenAPress) {
    EXPECT_TRUE(lockingHolds(kLockingPress, R"(
set Safe 1
set Closed 1
scans 2
expect DiagCode -32751
expect GuardLocked 0
expect UnlockGuard 0
expect Error 0
scans 2
expect DiagCode -32751
set Locked 1
scans 1
expect DiagCode -32765
expect GuardLocked 0
expect Error 0
scans 2
expect DiagCode -32765
set ResetButton 1
scans 1
expect DiagCode -32768
expect GuardLocked 1
)"));
}

TEST(SF_GuardLocking, WaitingForThePressAGuardUnlockedOrOpenedWaitsAgain) {
    EXPECT_TRUE(lockingHolds(kLockingPress, R"(
set Safe 1
set Closed 1
scans 2
set Locked 1
scans 1
expect DiagCode -32765
set Locked 0
scans 1
expect DiagCode -32751
set Locked 1
scans 1
expect DiagCode -32765
set Closed 0
scans 1
expect DiagCode -32751
)"));
}

TEST(SF_GuardLocking, AResetHeldWhileThePressIsAwaitedIsErrorC003UntilReleased) {
    EXPECT_TRUE(lockingHolds(kLockingPress, R"(
set Safe 1
set Closed 1
scans 2
set ResetButton 1
scans 1
expect DiagCode -32751
set Locked 1
scans 1
expect DiagCode -32765
# the held Reset comes before the guard being unlocked
set Locked 0
scans 1
expect DiagCode -16381
expect Error 1
expect GuardLocked 0
set Locked 1
scans 2
expect DiagCode -16381
set ResetButton 0
scans 1
expect DiagCode -32765
expect Error 0
set ResetButton 1
scans 1
expect DiagCode -32768
)"));
}

TEST(SF_GuardLocking, AutoResetLocksWithoutAPressButNotAtStart) {
    EXPECT_TRUE(lockingHolds(kLockingPress + " S_AutoReset=\"AutoReset\"", R"(
set AutoReset 1
set Safe 1
set Closed 1
set Locked 1
scans 3
expect DiagCode -32767
set Locked 0
scans 1
expect DiagCode -32751
# a held Reset is no static reset with S_AutoReset
set ResetButton 1
scans 1
set Locked 1
scans 1
expect DiagCode -32765
scans 1
expect DiagCode -32768
expect GuardLocked 1
)"));
}

TEST(SF_GuardLocking, ARequestWhileSafeUnlocksAndTheGuardClosedAndLockedAgainNeedsAPress) {
    EXPECT_TRUE(lockingHolds(kLockingPress, kLocked + R"(
# not safe: a request does nothing, and held it is no request
set Safe 0
set Unlock 1
scans 1
expect DiagCode -32768
set Safe 1
scans 2
expect DiagCode -32768
expect GuardLocked 1
set Unlock 0
scans 1
set Unlock 1
scans 1
expect DiagCode -32749
expect UnlockGuard 1
expect GuardLocked 0
expect Error 0
# unlocked and still closed: 8013 looks at the door and the request only
set Locked 0
scans 2
expect DiagCode -32749
set Closed 0
scans 1
expect DiagCode -32750
expect UnlockGuard 1
scans 2
expect DiagCode -32750
set Closed 1
scans 1
expect DiagCode -32749
set Unlock 0
scans 1
expect DiagCode -32751
expect UnlockGuard 0
expect GuardLocked 0
set Locked 1
scans 1
expect DiagCode -32765
set ResetButton 1
scans 1
expect DiagCode -32768
expect GuardLocked 1
)"));
}

TEST(SF_GuardLocking, OpeningAndReleasingTheRequestTogetherOpens) {
    EXPECT_TRUE(lockingHolds(kLockingPress, kLocked + R"(
set Unlock 1
scans 1
expect DiagCode -32749
# not closed comes before not requested in 8013's list
set Locked 0
set Closed 0
set Unlock 0
scans 1
expect DiagCode -32750
)"));
}

TEST(SF_GuardLocking, WaitingUnlockedARequestOrAnOpeningWhileSafeUnlocks) {
    EXPECT_TRUE(lockingHolds(kLockingPress, R"(
set Safe 1
set Closed 1
scans 2
expect DiagCode -32751
# the request is a level here
set Unlock 1
scans 1
expect DiagCode -32750
expect UnlockGuard 1
scans 1
expect DiagCode -32749
set Unlock 0
scans 1
expect DiagCode -32751
set Closed 0
scans 1
expect DiagCode -32750
)"));
}

TEST(SF_GuardLocking, LosingTheLockWhileLockedIsErrorC004UntilSafeAndAPress) {
    EXPECT_TRUE(lockingHolds(kLockingPress, kLocked + R"(
# the lost lock comes before a request
set Locked 0
set Unlock 1
scans 1
expect DiagCode -16380
expect Error 1
expect GuardLocked 0
expect UnlockGuard 0
expect Ready 1
set Safe 0
set Unlock 0
set Locked 1
scans 3
expect DiagCode -16380
set Safe 1
scans 1
expect DiagCode -32748
expect Error 0
expect GuardLocked 0
scans 2
expect DiagCode -32748
set ResetButton 1
scans 1
expect DiagCode -32751
scans 1
expect DiagCode -32765
)"));
}

TEST(SF_GuardLocking, OpeningWhileLockedIsErrorC004) {
    EXPECT_TRUE(lockingHolds(kLockingPress, kLocked + R"(
set Closed 0
scans 1
expect DiagCode -16380
expect GuardLocked 0
)"));
}

TEST(SF_GuardLocking, AResetHeldAfterAnErrorIsC002UntilReleasedAndNotSafeIsC004Again) {
    EXPECT_TRUE(lockingHolds(kLockingPress, kLocked + R"(
set ResetButton 1
scans 1
expect DiagCode -32768
set Locked 0
scans 1
expect DiagCode -16380
scans 1
expect DiagCode -32748
scans 1
expect DiagCode -16382
expect Error 1
# the held Reset comes before not safe
set Safe 0
scans 2
expect DiagCode -16382
set ResetButton 0
scans 1
expect DiagCode -32748
expect Error 0
scans 1
expect DiagCode -16380
set Safe 1
scans 1
expect DiagCode -32748
# not safe comes before a press
set Safe 0
set ResetButton 1
scans 1
expect DiagCode -16380
)"));
}

TEST(SF_GuardLocking, WaitingUnlockedNotSafeAndOpenIsErrorC004BeforeUnlocking) {
    EXPECT_TRUE(lockingHolds(kLockingPress, R"(
set Safe 1
set Closed 1
scans 2
expect DiagCode -32751
set Safe 0
scans 1
expect DiagCode -16380
)"));
    EXPECT_TRUE(lockingHolds(kLockingPress, R"(
set Safe 1
set Closed 1
scans 2
expect DiagCode -32751
set Safe 0
set Closed 0
scans 1
expect DiagCode -16380
)"));
    // open though locked, as a worn lock would report it
    EXPECT_TRUE(lockingHolds(kLockingPress, R"(
set Safe 1
set Closed 1
scans 2
expect DiagCode -32751
set Safe 0
set Closed 0
set Locked 1
scans 1
expect DiagCode -16380
)"));
}

TEST(SF_GuardLocking, UnlockedAndOpenNotSafeIsErrorC004) {
    EXPECT_TRUE(lockingHolds(kLockingPress, R"(
set Safe 1
scans 3
expect DiagCode -32750
expect UnlockGuard 1
set Safe 0
scans 1
expect DiagCode -16380
expect UnlockGuard 0
)"));
}
