// SPDX-License-Identifier: GPL-3.0-or-later
#include "TwoHandTest.h"

#include <string>

// SF_TwoHandControlTypeIII of Rungsmith_Safety: the scenarios of
// TwoHandScenarios.cpp, and its 500 ms synchronism to the scan: the second
// button seen 500 ms after the first passes, one scan later the timer decides
// (16#C004 -16380, 16#C005 -16379, 16#C006 -16378).

using rs::safetytest::twoHandHolds;
using rs::safetytest::TwoHandTest;

INSTANTIATE_TEST_SUITE_P(SF_TwoHandControlTypeIII, TwoHandTest,
                         ::testing::Values("SF_TwoHandControlTypeIII"));

namespace {

::testing::AssertionResult typeIIIHolds(const std::string& scenario) {
    return twoHandHolds("SF_TwoHandControlTypeIII", "", scenario);
}

// Presses button `first` alone (8005 for 1, 8006 for 2), lets its 500 ms pass
// and shows Button1 and Button2 as `buttons` ("1 0": only Button1 pressed) in
// the scan the timer has elapsed.
std::string timedOut(int first, const std::string& buttons) {
    const std::string waiting = first == 1 ? "-32763" : "-32762";
    return "scans 2\nset Button" + std::to_string(first) + " 1\nscans 1\nrun 500ms\n" +
           "expect DiagCode " + waiting + "\nset Button1 " + buttons.substr(0, 1) +
           "\nset Button2 " + buttons.substr(2, 1) + "\nscans 1\n";
}

// The error `diag` is held until both buttons are released.
std::string heldUntilBothReleased(const std::string& diag) {
    return "expect DiagCode " + diag +
           "\nexpect Error 1\nexpect Out 0\nexpect Ready 1\nset Button1 1\nset Button2 0\n"
           "scans 1\nexpect DiagCode " +
           diag + "\nset Button1 0\nset Button2 1\nscans 1\nexpect DiagCode " + diag +
           "\nset Button2 0\nscans 1\nexpect DiagCode -32764\nexpect Error 0\n";
}

} // namespace

TEST(SF_TwoHandControlTypeIII, Button2Exactly500msAfterButton1Enables) {
    EXPECT_TRUE(typeIIIHolds(R"(
scans 2
set Button1 1
scans 1
expect DiagCode -32763
run 490ms
expect DiagCode -32763
expect Error 0
set Button2 1
scans 1
expect DiagCode -32768
expect Out 1
)"));
}

TEST(SF_TwoHandControlTypeIII, Button1Exactly500msAfterButton2Enables) {
    EXPECT_TRUE(typeIIIHolds(R"(
scans 2
set Button2 1
scans 1
expect DiagCode -32762
run 490ms
expect DiagCode -32762
set Button1 1
scans 1
expect DiagCode -32768
expect Out 1
)"));
}

TEST(SF_TwoHandControlTypeIII, BothPressedOneScanLateIsErrorC006) {
    EXPECT_TRUE(typeIIIHolds(timedOut(1, "1 1") + heldUntilBothReleased("-16378")));
    EXPECT_TRUE(typeIIIHolds(timedOut(2, "1 1") + heldUntilBothReleased("-16378")));
}

TEST(SF_TwoHandControlTypeIII, Button1AloneWhenTheTimeRunsOutIsErrorC005) {
    EXPECT_TRUE(typeIIIHolds(timedOut(1, "1 0") + heldUntilBothReleased("-16379")));
    EXPECT_TRUE(typeIIIHolds(timedOut(2, "1 0") + heldUntilBothReleased("-16379")));
}

TEST(SF_TwoHandControlTypeIII, Button2AloneWhenTheTimeRunsOutIsErrorC004) {
    EXPECT_TRUE(typeIIIHolds(timedOut(1, "0 1") + heldUntilBothReleased("-16380")));
    EXPECT_TRUE(typeIIIHolds(timedOut(2, "0 1") + heldUntilBothReleased("-16380")));
}

TEST(SF_TwoHandControlTypeIII, BothReleasedJustAsTheTimeRunsOutWaitOnUntilTheNextPress) {
    // The model's elapsed timer comes first and has no transition for no
    // button pressed; the next press is then an error.
    for (const int first : {1, 2}) {
        const std::string waiting = first == 1 ? "-32763" : "-32762";
        EXPECT_TRUE(typeIIIHolds(timedOut(first, "0 0") + "expect DiagCode " + waiting +
                                 "\nexpect Error 0\nexpect Out 0\nrun 1s\nexpect DiagCode " +
                                 waiting + "\nset Button1 1\nscans 1\n" +
                                 heldUntilBothReleased("-16379")))
            << "first button " << first;
    }
}

TEST(SF_TwoHandControlTypeIII, ReleasingTheFirstButtonStopsTheTimeAndANewPressTimesAfresh) {
    EXPECT_TRUE(typeIIIHolds(R"(
scans 2
set Button1 1
scans 1
run 400ms
set Button1 0
scans 1
expect DiagCode -32764
run 1s
set Button1 1
scans 1
expect DiagCode -32763
run 490ms
expect DiagCode -32763
set Button2 1
scans 1
expect DiagCode -32768
set Button1 0
set Button2 0
scans 1
set Button2 1
scans 1
run 400ms
set Button2 0
scans 1
expect DiagCode -32764
set Button2 1
scans 1
run 490ms
set Button1 1
scans 1
expect DiagCode -32768
)"));
}
