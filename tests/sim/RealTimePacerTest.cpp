// SPDX-License-Identifier: GPL-3.0-or-later
#include "sim/RealTimePacer.h"

#include <gtest/gtest.h>

using rs::sim::RealTimePacer;

TEST(RealTimePacer, KeepsVirtualTimeWithTheWallClock) {
    RealTimePacer pacer(1.0);
    pacer.start(1000, 0);
    EXPECT_EQ(pacer.scansDue(1000, 0, 10, 100), 0);
    EXPECT_EQ(pacer.scansDue(1105, 0, 10, 100), 10); // 105 ms: ten whole scans
    EXPECT_EQ(pacer.scansDue(1105, 100, 10, 100), 0);
    EXPECT_EQ(pacer.scansDue(1130, 100, 10, 100), 3);
}

TEST(RealTimePacer, SpeedFactorAndAsFastAsPossible) {
    RealTimePacer fast(10.0);
    fast.start(0, 0);
    EXPECT_EQ(fast.scansDue(50, 0, 10, 1000), 50);
    RealTimePacer unlimited(0.0);
    unlimited.start(0, 0);
    EXPECT_EQ(unlimited.scansDue(0, 0, 10, 250), 250);
}

TEST(RealTimePacer, ChangingSpeedDoesNotJump) {
    RealTimePacer pacer(1.0);
    pacer.start(0, 0);
    EXPECT_EQ(pacer.scansDue(100, 0, 10, 100), 10);
    pacer.setSpeed(10.0, 100, 100);
    EXPECT_EQ(pacer.scansDue(100, 100, 10, 1000), 0);
    EXPECT_EQ(pacer.scansDue(110, 100, 10, 1000), 10);
}

TEST(RealTimePacer, ABacklogIsDroppedNotReplayed) {
    RealTimePacer pacer(1.0);
    pacer.start(0, 0);
    EXPECT_EQ(pacer.scansDue(10000, 0, 10, 20), 20);  // 10 s behind: only 20 scans now
    EXPECT_EQ(pacer.scansDue(10000, 200, 10, 20), 0); // and no debt afterwards
    EXPECT_EQ(pacer.scansDue(10050, 200, 10, 20), 5);
}
