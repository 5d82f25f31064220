// SPDX-License-Identifier: GPL-3.0-or-later
#include "SafetyBench.h"

#include <gtest/gtest.h>

#include <string>

// SF_ModeSelector of Rungsmith_Safety walked through every state and
// transition of the PLCopen state machine as the public model has it
// (docs/safety-blocks.md). DiagCodes read as signed registers:
// 16#8000 -32768, 16#8004 -32764, 16#8005 -32763, 16#C001 -16383,
// 16#C002 -16382, 16#C003 -16381, 16#C004 -16380.

using rs::safetytest::holdsOnBothInstructionSets;

namespace {

// A unit with one instance using three modes (Mode0 to Mode2, S_Mode3 to
// S_Mode7 open); `bindings` adds further pins (ModeMonitorTime among them:
// open it is 0).
::testing::AssertionResult selectorHolds(const std::string& bindings, const std::string& scenario) {
    const std::string names = "! I0.0=Act\n! I0.1=Mode0\n! I0.2=Mode1\n! I0.3=Mode2\n"
                              "! I0.4=Unlock\n! I0.5=SetMode\n! I0.6=AutoSet\n! I0.7=ResetButton\n"
                              "! M0.0=Ready\n! M0.1=Sel0\n! M0.2=Sel1\n! M0.3=Sel2\n"
                              "! M0.4=AnySel\n! M0.5=Error\n! R0.0=DiagCode\n! R0.1=Limit\n";
    const std::string record =
        ";@block SF_ModeSelector S_Mode0=\"Mode0\" S_Mode1=\"Mode1\" S_Mode2=\"Mode2\" "
        "S_Unlock=\"Unlock\" Ready=\"Ready\" S_Mode0Sel=\"Sel0\" S_Mode1Sel=\"Sel1\" "
        "S_Mode2Sel=\"Sel2\" S_AnyModeSel=\"AnySel\" Error=\"Error\" DiagCode=\"DiagCode\" " +
        bindings + "\n;@end\n";
    return holdsOnBothInstructionSets(names, record, scenario);
}

const std::string kModeTime = "ModeMonitorTime=\"0s05\" ";
const std::string kModePress = kModeTime + "S_SetMode=\"SetMode\" Reset=\"ResetButton\"";

// Mode1 taken with a press of S_SetMode, unlocked.
const std::string kMode1Selected = R"(
set Unlock 1
set Mode1 1
scans 2
expect DiagCode -32763
set SetMode 1
scans 1
expect DiagCode -32768
set SetMode 0
)";

} // namespace

TEST(SF_ModeSelector, ActivateOffHoldsStateZeroWithEveryOutputOff) {
    EXPECT_TRUE(selectorHolds(kModePress + " Activate=\"Act\"", R"(
set Unlock 1
set Mode1 1
scans 2
expect DiagCode 0
expect Ready 0
expect AnySel 0
expect Sel1 0
expect Error 0
set Act 1
scans 1
# the first active scan: 0000 -> 8005
expect DiagCode -32763
expect Ready 1
expect AnySel 0
set SetMode 1
scans 1
expect DiagCode -32768
expect Sel1 1
expect AnySel 1
set Act 0
scans 1
expect DiagCode 0
expect Ready 0
expect Sel1 0
expect AnySel 0
# Activate off also leaves an error state
set Act 1
set Mode2 1
scans 2
expect DiagCode -16383
expect Error 1
set Act 0
scans 1
expect DiagCode 0
expect Error 0
expect Ready 0
)"));
}

TEST(SF_ModeSelector, WithoutSetModeOrAutoSetModeNothingIsTaken) {
    // A mode on from activation on is no mode appearing: no time runs.
    EXPECT_TRUE(selectorHolds(kModeTime, R"(
set Unlock 1
set Mode1 1
scans 1
expect DiagCode -32763
expect Ready 1
expect AnySel 0
expect Error 0
run 1s
expect DiagCode -32763
expect Sel1 0
expect Error 0
)"));
}

TEST(SF_ModeSelector, APressOfSetModeTakesTheOneModeOnWhileUnlocked) {
    EXPECT_TRUE(selectorHolds(kModePress, R"(
scans 2
# no mode, or locked: a press takes nothing
set Unlock 1
set SetMode 1
scans 1
expect DiagCode -32763
set SetMode 0
set Unlock 0
set Mode1 1
scans 1
set SetMode 1
scans 1
expect DiagCode -32763
# held from before: no edge
set Unlock 1
scans 2
expect DiagCode -32763
set SetMode 0
scans 1
set SetMode 1
scans 1
expect DiagCode -32768
expect Sel1 1
expect Sel0 0
expect Sel2 0
expect AnySel 1
expect Error 0
expect Ready 1
scans 3
expect DiagCode -32768
expect Sel1 1
)"));
}

TEST(SF_ModeSelector, AutoSetModeTakesTheOneModeOnAtOnce) {
    EXPECT_TRUE(selectorHolds(kModeTime + "AutoSetMode=\"AutoSet\"", R"(
set AutoSet 1
set Unlock 1
set Mode2 1
scans 1
expect DiagCode -32763
scans 1
expect DiagCode -32768
expect Sel2 1
expect AnySel 1
# a change drops the selection, and the new mode is taken in the next scan
set Mode2 0
set Mode0 1
scans 1
expect DiagCode -32763
expect Sel2 0
expect Sel0 0
expect AnySel 0
scans 1
expect DiagCode -32768
expect Sel0 1
)"));
}

TEST(SF_ModeSelector, AModeInputChangingDropsTheSelectionUntilTheNextPress) {
    EXPECT_TRUE(selectorHolds(kModePress, kMode1Selected + R"(
set Mode1 0
set Mode2 1
scans 1
expect DiagCode -32763
expect Sel1 0
expect Sel2 0
expect AnySel 0
expect Error 0
scans 2
expect DiagCode -32763
set SetMode 1
scans 1
expect DiagCode -32768
expect Sel2 1
expect Sel1 0
set SetMode 0
# no mode at all drops it too
set Mode2 0
scans 1
expect DiagCode -32763
expect AnySel 0
)"));
}

TEST(SF_ModeSelector, UnlockOffFreezesTheSelectionAndUnlockingTakesTheModeInputsAsTheyAre) {
    EXPECT_TRUE(selectorHolds(kModePress, kMode1Selected + R"(
set Unlock 0
scans 1
expect DiagCode -32764
expect Sel1 1
expect AnySel 1
expect Error 0
# locked: changes and even two modes are not looked at
set Mode1 0
set Mode2 1
scans 2
expect DiagCode -32764
expect Sel1 1
expect Sel2 0
set Mode0 1
scans 2
expect DiagCode -32764
set Mode0 0
set Unlock 1
scans 1
expect DiagCode -32768
expect Sel2 1
expect Sel1 0
expect AnySel 1
scans 2
expect DiagCode -32768
expect Sel2 1
)"));
}

TEST(SF_ModeSelector, UnlockingWithTwoModesOnShowsBothForOneScanThenC001) {
    EXPECT_TRUE(selectorHolds(kModePress, kMode1Selected + R"(
set Unlock 0
scans 1
set Mode2 1
scans 1
expect DiagCode -32764
set Unlock 1
scans 1
expect DiagCode -32768
expect Sel1 1
expect Sel2 1
scans 1
expect DiagCode -16383
expect Sel1 0
expect Sel2 0
)"));
}

TEST(SF_ModeSelector, TwoModesOnAreErrorC001UntilAPress) {
    EXPECT_TRUE(selectorHolds(kModePress, R"(
set Unlock 1
scans 2
set Mode0 1
set Mode2 1
scans 1
expect DiagCode -16383
expect Error 1
expect AnySel 0
expect Sel0 0
expect Ready 1
set Mode2 0
scans 3
expect DiagCode -16383
set ResetButton 1
scans 1
expect DiagCode -32763
expect Error 0
)"));
}

TEST(SF_ModeSelector, ASecondModeComesBeforeTheChangeInTheSelectedState) {
    EXPECT_TRUE(selectorHolds(kModePress, kMode1Selected + R"(
set Mode0 1
set Unlock 0
scans 1
expect DiagCode -16383
expect Sel1 0
expect AnySel 0
)"));
}

TEST(SF_ModeSelector, AResetHeldInC001IsC003UntilReleased) {
    EXPECT_TRUE(selectorHolds(kModePress, R"(
set Unlock 1
set ResetButton 1
set Mode0 1
set Mode1 1
scans 2
expect DiagCode -16383
scans 1
expect DiagCode -16381
expect Error 1
set Mode1 0
scans 2
expect DiagCode -16381
set ResetButton 0
scans 1
expect DiagCode -16383
set ResetButton 1
scans 1
expect DiagCode -32763
)"));
}

TEST(SF_ModeSelector, AModeTakenExactlyModeMonitorTimeAfterItAppearedIsSelected) {
    EXPECT_TRUE(selectorHolds(kModePress, R"(
set Unlock 1
scans 2
set Mode1 1
scans 1
expect DiagCode -32763
run 40ms
expect DiagCode -32763
set SetMode 1
scans 1
expect DiagCode -32768
expect Sel1 1
)"));
}

TEST(SF_ModeSelector, AModeNotTakenWithinModeMonitorTimeIsErrorC002UntilAPress) {
    EXPECT_TRUE(selectorHolds(kModePress, R"(
set Unlock 1
scans 2
set Mode1 1
scans 1
run 50ms
expect DiagCode -32763
expect Error 0
# one scan late: the timer comes before the press
set SetMode 1
scans 1
expect DiagCode -16382
expect Error 1
expect AnySel 0
expect Sel1 0
set SetMode 0
scans 3
expect DiagCode -16382
set ResetButton 1
scans 1
expect DiagCode -32763
expect Error 0
# the mode is still on, so none appeared: it may be taken any time later
run 1s
expect DiagCode -32763
set SetMode 1
scans 1
expect DiagCode -32768
)"));
}

TEST(SF_ModeSelector, AResetHeldInC002IsC004UntilReleased) {
    EXPECT_TRUE(selectorHolds(kModePress, R"(
set Unlock 1
set ResetButton 1
scans 2
set Mode1 1
scans 1
run 60ms
expect DiagCode -16382
scans 1
expect DiagCode -16380
expect Error 1
set ResetButton 0
scans 1
expect DiagCode -16382
set ResetButton 1
scans 1
expect DiagCode -32763
)"));
}

TEST(SF_ModeSelector, TwoModesComeBeforeTheTimeRunningOut) {
    EXPECT_TRUE(selectorHolds(kModePress, R"(
set Unlock 1
scans 2
set Mode1 1
scans 1
run 50ms
set Mode2 1
scans 1
expect DiagCode -16383
)"));
}

TEST(SF_ModeSelector, NoModeStopsTheTimeAndTheNextModeTimesAfresh) {
    EXPECT_TRUE(selectorHolds(kModePress, R"(
set Unlock 1
scans 2
set Mode1 1
scans 1
run 40ms
set Mode1 0
scans 1
run 1s
expect DiagCode -32763
expect Error 0
set Mode2 1
scans 1
run 50ms
expect DiagCode -32763
scans 1
expect DiagCode -16382
)"));
}

TEST(SF_ModeSelector, NoModeForOneScanRestartsTheTime) {
    EXPECT_TRUE(selectorHolds(kModePress, R"(
set Unlock 1
scans 2
set Mode1 1
scans 1
run 30ms
set Mode1 0
scans 1
set Mode1 1
scans 1
run 40ms
expect DiagCode -32763
set SetMode 1
scans 1
expect DiagCode -32768
)"));
}

TEST(SF_ModeSelector, NoModeInTheScanTheTimeRunsOutIsNoError) {
    EXPECT_TRUE(selectorHolds(kModePress, R"(
set Unlock 1
scans 2
set Mode1 1
scans 1
run 50ms
set Mode1 0
scans 1
expect DiagCode -32763
expect Error 0
run 1s
expect DiagCode -32763
)"));
}

TEST(SF_ModeSelector, SwitchingFromOneModeToAnotherDoesNotRestartTheTime) {
    EXPECT_TRUE(selectorHolds(kModePress, R"(
set Unlock 1
scans 2
set Mode1 1
scans 1
run 30ms
set Mode1 0
set Mode2 1
run 20ms
expect DiagCode -32763
scans 1
expect DiagCode -16382
)"));
}

TEST(SF_ModeSelector, TheModesAreWatchedOnlyWhileWaitingAndActive) {
    // A mode appearing in a scan with Activate off is no edge then; the
    // first scan back in 8005 sees it appear.
    EXPECT_TRUE(selectorHolds(kModePress + " Activate=\"Act\"", R"(
set Act 1
set Unlock 1
scans 3
expect DiagCode -32763
set Mode1 1
set Act 0
scans 1
expect DiagCode 0
set Act 1
scans 1
expect DiagCode -32763
scans 1
run 50ms
expect DiagCode -32763
scans 1
expect DiagCode -16382
)"));
}

TEST(SF_ModeSelector, AModeMonitorTimeInARegisterOfZeroFailsEveryModeThatAppears) {
    EXPECT_TRUE(selectorHolds("ModeMonitorTime=\"Limit\" S_SetMode=\"SetMode\" "
                              "Reset=\"ResetButton\"",
                              R"(
set Limit 0
set Unlock 1
scans 2
set Mode1 1
scans 1
expect DiagCode -32763
set SetMode 1
scans 1
expect DiagCode -16382
set Limit 3
set SetMode 0
set Mode1 0
set ResetButton 1
scans 1
expect DiagCode -32763
scans 1
set Mode1 1
scans 1
run 20ms
set SetMode 1
scans 1
expect DiagCode -32768
)"));
}

TEST(SF_ModeSelector, EachOfTheEightModesIsSelectedAloneOnItsOwnOutput) {
    std::string names = "! I0.0=Unlock\n! I0.1=SetMode\n! R0.0=DiagCode\n! M0.0=AnySel\n";
    std::string record = ";@block SF_ModeSelector S_Unlock=\"Unlock\" S_SetMode=\"SetMode\" "
                         "ModeMonitorTime=\"0s05\" S_AnyModeSel=\"AnySel\" DiagCode=\"DiagCode\"";
    for (int mode = 0; mode < 8; ++mode) {
        const std::string n = std::to_string(mode);
        names += "! M0.1" + n + "=Mode" + n + "\n! M0.2" + n + "=Sel" + n + "\n";
        record += " S_Mode" + n + "=\"Mode" + n + "\" S_Mode" + n + "Sel=\"Sel" + n + "\"";
    }
    record += "\n;@end\n";
    for (int mode = 0; mode < 8; ++mode) {
        const std::string n = std::to_string(mode);
        const std::string next = std::to_string((mode + 1) % 8);
        std::string scenario = "set Unlock 1\nscans 1\nset Mode" + n +
                               " 1\nscans 1\nexpect DiagCode -32763\nset SetMode 1\nscans 1\n"
                               "expect DiagCode -32768\nexpect AnySel 1\n";
        for (int other = 0; other < 8; ++other)
            scenario += "expect Sel" + std::to_string(other) + (other == mode ? " 1\n" : " 0\n");
        // it stays selected, and locked it keeps its output
        scenario +=
            "scans 2\nexpect DiagCode -32768\nset Unlock 0\nscans 1\nexpect DiagCode -32764\n"
            "expect Sel" +
            n + " 1\nscans 2\nexpect Sel" + n +
            " 1\nset Unlock 1\nscans 2\nexpect DiagCode -32768\nexpect Sel" + n + " 1\n";
        // switched off, the mode drops the selection; with another one it is two modes
        scenario += "set Mode" + n + " 0\nscans 1\nexpect DiagCode -32763\nexpect Sel" + n +
                    " 0\nset Mode" + n + " 1\nset Mode" + next +
                    " 1\nscans 1\nexpect DiagCode -16383\n";
        EXPECT_TRUE(holdsOnBothInstructionSets(names, record, scenario)) << "mode " << n;
    }
}
