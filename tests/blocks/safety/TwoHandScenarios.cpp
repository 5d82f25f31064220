// SPDX-License-Identifier: GPL-3.0-or-later
#include "TwoHandTest.h"

// The state machine SF_TwoHandControlTypeII and SF_TwoHandControlTypeIII
// share, walked through every state and transition (docs/safety-blocks.md),
// every press within Type III's 500 ms. DiagCodes read as signed registers:
// 16#8000 -32768, 16#8001 -32767, 16#8004 -32764, 16#8005 -32763,
// 16#8006 -32762, 16#8007 -32761, 16#8008 -32760, 16#8009 -32759,
// 16#8019 -32743, 16#C001 -16383, 16#C002 -16382, 16#C003 -16381.

using rs::safetytest::TwoHandTest;

TEST_P(TwoHandTest, ActivateOffHoldsStateZeroWithEveryOutputOff) {
    EXPECT_TRUE(holds("Activate=\"Act\"", R"(
set Button1 1
set Button2 1
scans 2
expect DiagCode 0
expect Ready 0
expect Out 0
expect Error 0
set Button1 0
set Button2 0
set Act 1
scans 1
# the first active scan: 0000 -> 8001
expect DiagCode -32767
expect Ready 1
expect Out 0
scans 1
expect DiagCode -32764
set Button1 1
set Button2 1
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
scans 2
expect DiagCode -16381
expect Error 1
set Act 0
scans 1
expect DiagCode 0
expect Error 0
expect Ready 0
)"));
}

TEST_P(TwoHandTest, AnOpenActivateIsOnAndWithBothButtonsReleasedAwaitsAPress) {
    EXPECT_TRUE(holds("", R"(
scans 1
expect DiagCode -32767
expect Ready 1
expect Out 0
expect Error 0
scans 1
expect DiagCode -32764
run 1s
expect DiagCode -32764
expect Out 0
expect Error 0
)"));
}

TEST_P(TwoHandTest, Button1PressedAtActivationIsErrorC001UntilBothAreReleased) {
    EXPECT_TRUE(holds("", R"(
set Button1 1
scans 2
expect DiagCode -16383
expect Error 1
expect Out 0
expect Ready 1
set Button2 1
scans 2
expect DiagCode -16383
expect Out 0
set Button1 0
scans 2
expect DiagCode -16383
set Button2 0
scans 1
expect DiagCode -32764
expect Error 0
)"));
}

TEST_P(TwoHandTest, Button2PressedAtActivationIsErrorC002UntilBothAreReleased) {
    EXPECT_TRUE(holds("", R"(
set Button2 1
scans 2
expect DiagCode -16382
expect Error 1
expect Out 0
set Button1 1
scans 1
expect DiagCode -16382
set Button2 0
scans 2
expect DiagCode -16382
set Button1 0
scans 1
expect DiagCode -32764
expect Error 0
)"));
}

TEST_P(TwoHandTest, BothPressedAtActivationIsErrorC003UntilBothAreReleased) {
    EXPECT_TRUE(holds("", R"(
set Button1 1
set Button2 1
scans 2
expect DiagCode -16381
expect Error 1
expect Out 0
set Button1 0
scans 1
expect DiagCode -16381
set Button2 0
scans 1
expect DiagCode -32764
expect Error 0
set Button1 1
set Button2 1
scans 1
expect DiagCode -32768
expect Out 1
)"));
}

TEST_P(TwoHandTest, BothPressedInOneScanEnableUntilBothAreReleased) {
    EXPECT_TRUE(holds("", R"(
scans 2
set Button1 1
set Button2 1
scans 1
expect DiagCode -32768
expect Out 1
expect Ready 1
expect Error 0
scans 3
expect DiagCode -32768
expect Out 1
set Button1 0
set Button2 0
scans 1
expect DiagCode -32764
expect Out 0
)"));
}

TEST_P(TwoHandTest, Button1ThenButton2Enable) {
    EXPECT_TRUE(holds("", R"(
scans 2
set Button1 1
scans 1
expect DiagCode -32763
expect Out 0
expect Error 0
scans 3
expect DiagCode -32763
set Button2 1
scans 1
expect DiagCode -32768
expect Out 1
)"));
}

TEST_P(TwoHandTest, Button2ThenButton1Enable) {
    EXPECT_TRUE(holds("", R"(
scans 2
set Button2 1
scans 1
expect DiagCode -32762
expect Out 0
expect Error 0
scans 3
expect DiagCode -32762
set Button1 1
scans 1
expect DiagCode -32768
expect Out 1
)"));
}

TEST_P(TwoHandTest, ReleasingTheOnlyPressedButtonAwaitsANewPress) {
    EXPECT_TRUE(holds("", R"(
scans 2
set Button1 1
scans 1
expect DiagCode -32763
set Button1 0
scans 1
expect DiagCode -32764
set Button2 1
scans 1
expect DiagCode -32762
set Button2 0
scans 1
expect DiagCode -32764
expect Error 0
)"));
}

TEST_P(TwoHandTest, SwappingButton1ForButton2IsAWrongSequenceUntilBothAreReleased) {
    EXPECT_TRUE(holds("", R"(
scans 2
set Button1 1
scans 1
set Button1 0
set Button2 1
scans 1
expect DiagCode -32743
expect Out 0
expect Error 0
expect Ready 1
# pressing both does not enable from 8019
set Button1 1
scans 2
expect DiagCode -32743
expect Out 0
set Button2 0
scans 1
expect DiagCode -32743
set Button1 0
scans 1
expect DiagCode -32764
)"));
}

TEST_P(TwoHandTest, SwappingButton2ForButton1IsAWrongSequenceUntilBothAreReleased) {
    EXPECT_TRUE(holds("", R"(
scans 2
set Button2 1
scans 1
set Button2 0
set Button1 1
scans 1
expect DiagCode -32743
expect Out 0
set Button2 1
scans 1
expect DiagCode -32743
set Button1 0
set Button2 0
scans 1
expect DiagCode -32764
)"));
}

TEST_P(TwoHandTest, AfterButton2IsReleasedTheOutputStaysOffUntilBothAreReleased) {
    EXPECT_TRUE(holds("", R"(
scans 2
set Button1 1
set Button2 1
scans 1
expect DiagCode -32768
set Button2 0
scans 1
expect DiagCode -32761
expect Out 0
expect Error 0
scans 2
expect DiagCode -32761
set Button2 1
scans 1
expect DiagCode -32759
expect Out 0
scans 2
expect DiagCode -32759
expect Out 0
set Button1 0
scans 1
expect DiagCode -32760
expect Out 0
scans 2
expect DiagCode -32760
set Button1 1
scans 1
expect DiagCode -32759
set Button2 0
scans 1
expect DiagCode -32761
set Button1 0
set Button2 1
scans 1
expect DiagCode -32760
set Button1 1
set Button2 0
scans 1
expect DiagCode -32761
set Button1 0
scans 1
expect DiagCode -32764
expect Out 0
)"));
}

TEST_P(TwoHandTest, AfterButton1IsReleasedTheOutputStaysOffUntilBothAreReleased) {
    EXPECT_TRUE(holds("", R"(
scans 2
set Button1 1
set Button2 1
scans 1
set Button1 0
scans 1
expect DiagCode -32760
expect Out 0
set Button2 0
scans 1
expect DiagCode -32764
set Button1 1
set Button2 1
scans 1
expect DiagCode -32768
set Button1 0
scans 1
set Button1 1
scans 1
expect DiagCode -32759
set Button1 0
set Button2 0
scans 1
expect DiagCode -32764
expect Out 0
set Button1 1
set Button2 1
scans 1
expect DiagCode -32768
expect Out 1
)"));
}
