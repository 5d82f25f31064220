// SPDX-License-Identifier: GPL-3.0-or-later
#include "TwoHandTest.h"

// SF_TwoHandControlTypeII of Rungsmith_Safety: the scenarios of
// TwoHandScenarios.cpp, and that Type II has no synchronism time.

using rs::safetytest::twoHandHolds;
using rs::safetytest::TwoHandTest;

INSTANTIATE_TEST_SUITE_P(SF_TwoHandControlTypeII, TwoHandTest,
                         ::testing::Values("SF_TwoHandControlTypeII"));

TEST(SF_TwoHandControlTypeII, TheSecondButtonMayFollowTheFirstAnyTimeLater) {
    EXPECT_TRUE(twoHandHolds("SF_TwoHandControlTypeII", "", R"(
scans 2
set Button1 1
scans 1
run 10s
expect DiagCode -32763
expect Error 0
set Button2 1
scans 1
expect DiagCode -32768
expect Out 1
set Button1 0
set Button2 0
scans 1
set Button2 1
scans 1
run 10s
expect DiagCode -32762
set Button1 1
scans 1
expect DiagCode -32768
)"));
}
