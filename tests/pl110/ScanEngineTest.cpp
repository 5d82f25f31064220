// SPDX-License-Identifier: GPL-3.0-or-later
#include "RandomProgram.h"

#include "pl110/ProgramCheck.h"
#include "pl110/ProgramText.h"
#include "pl110/ScanEngine.h"
#include "sim/Conduction.h"

#include <gtest/gtest.h>

namespace rs::pl110 {
namespace {

Program checked(std::string_view body) {
    ProgramReading reading = readProgram("$target PL110\n" + std::string(body));
    EXPECT_TRUE(reading.diagnostics.empty()) << reading.diagnostics.front().message;
    const lang::Diagnostics problems = checkProgram(reading.program);
    EXPECT_TRUE(problems.empty()) << problems.front().message;
    return reading.program;
}

Address at(std::string_view word) {
    return readAddress(word).address;
}

struct Plant {
    explicit Plant(std::string_view body, int cycleMs = 10) : engine(checked(body), cycleMs) {}
    void set(std::string_view input, bool on) { engine.memory().setBit(at(input), on); }
    bool bit(std::string_view word) const { return engine.memory().bit(at(word)); }
    std::int32_t value(std::string_view word) const {
        return engine.memory().value(asWord(at(word)));
    }
    void scans(int count) {
        for (int i = 0; i < count; ++i)
            engine.scan();
    }
    ScanEngine engine;
};

TEST(Pl110Scan, CoilsFollowTheirRungAndASelfHoldLatches) {
    Plant plant("MAIN\nQ1 = I1 * /I2 + Q1 * /I2\n");
    plant.scans(1);
    EXPECT_FALSE(plant.bit("Q1"));
    plant.set("I1", true);
    plant.scans(1);
    EXPECT_TRUE(plant.bit("Q1"));
    plant.set("I1", false);
    plant.scans(5);
    EXPECT_TRUE(plant.bit("Q1"));
    plant.set("I2", true);
    plant.scans(1);
    EXPECT_FALSE(plant.bit("Q1"));
}

TEST(Pl110Scan, InitRunsOnceBeforeTheFirstScanWithTheFirstScanMarkerOn) {
    Plant plant("INIT\n(VW1 = VW1 + 1)\nM1 = SM0.1\nMAIN\nM2 = SM0.1\n(VW2 = VW2 + 1)\n");
    plant.scans(1);
    EXPECT_EQ(plant.value("VW1"), 1);
    EXPECT_TRUE(plant.bit("M1"));
    EXPECT_TRUE(plant.bit("M2"));
    plant.scans(3);
    EXPECT_EQ(plant.value("VW1"), 1);
    EXPECT_EQ(plant.value("VW2"), 4);
    EXPECT_FALSE(plant.bit("M2"));
}

TEST(Pl110Scan, OnDelayCountsInItsBaseAndTakesItsPresetFromAWord) {
    // 100 ms base, preset 5 (0.5 s) from VW0, 10 ms scans.
    Plant plant("INIT\n(VW0 = 5)\nMAIN\nTON(T1, 100ms, VW0) = I1\nQ1 = T1\n");
    plant.set("I1", true);
    plant.scans(50); // the first scan starts the timer at 0; 49 more are 490 ms
    EXPECT_EQ(plant.value("T1"), 4);
    EXPECT_EQ(plant.value("PT1"), 5);
    EXPECT_FALSE(plant.bit("Q1"));
    plant.scans(1);
    EXPECT_EQ(plant.value("T1"), 5);
    EXPECT_TRUE(plant.bit("Q1"));
    plant.scans(400000);
    EXPECT_EQ(plant.value("T1"), 32767); // stops at 32767
    plant.set("I1", false);
    plant.scans(1);
    EXPECT_EQ(plant.value("T1"), 0);
    EXPECT_FALSE(plant.bit("T1"));
}

TEST(Pl110Scan, OffDelayHoldsAfterTheCoilGoesOffAndNeedsAFallingEdge) {
    Plant plant("MAIN\nTOFF(T2, 10ms, 30) = I1\nQ1 = T2\n");
    plant.scans(10);
    EXPECT_FALSE(plant.bit("Q1")); // never on: nothing to hold
    plant.set("I1", true);
    plant.scans(1);
    EXPECT_TRUE(plant.bit("Q1"));
    plant.set("I1", false);
    plant.scans(30); // the falling scan at 0, then 29 x 10 ms
    EXPECT_TRUE(plant.bit("Q1"));
    plant.scans(1);
    EXPECT_FALSE(plant.bit("Q1"));
    EXPECT_EQ(plant.value("T2"), 30);
    plant.set("I1", true);
    plant.scans(1);
    plant.set("I1", false);
    plant.scans(10); // an off time shorter than the preset keeps it on
    plant.set("I1", true);
    plant.scans(1);
    EXPECT_TRUE(plant.bit("Q1"));
    EXPECT_EQ(plant.value("T2"), 0);
}

TEST(Pl110Scan, RetentiveTimerAccumulatesUntilAMoveClearsIt) {
    Plant plant("MAIN\nTONR(T3, 1s, 2) = I1\n(T3 = 0) = I2\nQ1 = T3\n", 100);
    plant.set("I1", true);
    plant.scans(11); // 1 s
    plant.set("I1", false);
    plant.scans(50);
    EXPECT_EQ(plant.value("T3"), 1);
    plant.set("I1", true);
    plant.scans(11);
    EXPECT_TRUE(plant.bit("Q1"));
    plant.set("I1", false);
    plant.scans(5);
    EXPECT_TRUE(plant.bit("Q1"));
    plant.set("I2", true);
    plant.scans(2);
    EXPECT_EQ(plant.value("T3"), 0);
    EXPECT_FALSE(plant.bit("Q1"));
}

TEST(Pl110Scan, UpCounterCountsEdgesAndComparesAtTheEndOfTheScan) {
    Plant plant(
        "MAIN\nQ1 = C1\nMUP(C1, UP, 3) = I1\nMUP(C1, DOWN, 3) = I2\nMUP(C1, RESET, 3) = I3\n");
    for (int pulse = 0; pulse < 3; ++pulse) {
        plant.set("I1", true);
        plant.scans(2);
        plant.set("I1", false);
        plant.scans(2);
    }
    EXPECT_EQ(plant.value("C1"), 3);
    EXPECT_TRUE(plant.bit("C1"));
    EXPECT_TRUE(plant.bit("Q1"));
    plant.set("I2", true);
    plant.scans(1);
    EXPECT_EQ(plant.value("C1"), 2);
    EXPECT_FALSE(plant.bit("C1"));
    EXPECT_TRUE(plant.bit("Q1")); // Q1 read C1 before the end-of-scan compare
    plant.scans(1);
    EXPECT_FALSE(plant.bit("Q1"));
    plant.set("I3", true);
    plant.scans(1);
    EXPECT_EQ(plant.value("C1"), 0);
}

TEST(Pl110Scan, DownCounterLoadsItsPresetOnResetAndStopsAtZero) {
    Plant plant("MAIN\nMDOWN(C2, DOWN, 2) = I1\nMDOWN(C2, RESET, 2) = I3\n");
    plant.set("I3", true);
    plant.scans(1);
    EXPECT_EQ(plant.value("C2"), 2);
    EXPECT_FALSE(plant.bit("C2"));
    plant.set("I3", false);
    for (int pulse = 0; pulse < 4; ++pulse) {
        plant.set("I1", pulse % 2 == 0);
        plant.scans(1);
    }
    EXPECT_EQ(plant.value("C2"), 0);
    EXPECT_TRUE(plant.bit("C2"));
    plant.set("I1", true);
    plant.scans(1);
    EXPECT_EQ(plant.value("C2"), 0);
}

TEST(Pl110Scan, BistableRelayChangesOncePerEnergisation) {
    Plant plant("MAIN\nB1 = I1\nQ1 = B1\n");
    plant.set("I1", true);
    plant.scans(4);
    EXPECT_TRUE(plant.bit("Q1"));
    plant.set("I1", false);
    plant.scans(1);
    EXPECT_TRUE(plant.bit("Q1"));
    plant.set("I1", true);
    plant.scans(1);
    EXPECT_FALSE(plant.bit("Q1"));
}

TEST(Pl110Scan, NotAndEdgesActOnThePowerReachingThem) {
    Plant plant("MAIN\nQ1 = I1 * I2 * NOT\nQ2 = I1 * P\nQ3 = I1 * N\nQ4 = I1 * (I2 + NOT)\n");
    plant.scans(1);
    EXPECT_TRUE(plant.bit("Q1"));
    EXPECT_TRUE(plant.bit("Q4")); // NOT of the power reaching it: not I1
    plant.set("I1", true);
    plant.scans(1);
    EXPECT_TRUE(plant.bit("Q1"));
    EXPECT_TRUE(plant.bit("Q2"));
    EXPECT_FALSE(plant.bit("Q4"));
    plant.scans(1);
    EXPECT_FALSE(plant.bit("Q2"));
    plant.set("I2", true);
    plant.scans(1);
    EXPECT_FALSE(plant.bit("Q1"));
    EXPECT_TRUE(plant.bit("Q4"));
    plant.set("I1", false);
    plant.scans(1);
    EXPECT_TRUE(plant.bit("Q3"));
    plant.scans(1);
    EXPECT_FALSE(plant.bit("Q3"));
}

TEST(Pl110Scan, FormulasWrapToTheirWidthAndDivisionByZeroKeepsTheDestination) {
    Plant plant("MAIN\n(VW1 = 32767 + 1)\n(VD2 = 32767 + 1)\n(VW5 = 7)\n(VW5 = VW5 / VW6)\n"
                "(VW7 = -7 / 2)\n(VW8 = 1 << 15)\n(VW9 = -8 >> 1)\n(VW10 = 12 ^ 10)\n"
                "SBIT(V11.3) = I1\nRBIT(V11.3) = I2\n");
    plant.set("I1", true);
    plant.scans(1);
    EXPECT_EQ(plant.value("VW1"), -32768);
    EXPECT_EQ(plant.value("VD2"), 32768);
    EXPECT_EQ(plant.value("VW2"), 0); // VD2's high word
    EXPECT_EQ(plant.value("VW3"), -32768);
    EXPECT_EQ(plant.value("VW5"), 7);
    EXPECT_EQ(plant.value("VW7"), -3);
    EXPECT_EQ(plant.value("VW8"), -32768);
    EXPECT_EQ(plant.value("VW9"), -4);
    EXPECT_EQ(plant.value("VW10"), 6);
    EXPECT_EQ(plant.value("VW11"), 8);
    EXPECT_TRUE(plant.bit("V11.3"));
    plant.set("I1", false);
    plant.set("I2", true);
    plant.scans(1);
    EXPECT_FALSE(plant.bit("V11.3"));
}

TEST(Pl110Scan, ClocksAndTestModeFollowTheSpecialMarkers) {
    Plant plant("MAIN\nQ1 = SM0.3\nQ2 = SM0.4\nQ3 = I1\n", 100);
    plant.scans(1);
    EXPECT_TRUE(plant.bit("Q1"));
    EXPECT_TRUE(plant.bit("Q2"));
    plant.scans(1);
    EXPECT_FALSE(plant.bit("Q2"));
    plant.scans(4); // 500 ms: the 1 s clock's off half
    EXPECT_FALSE(plant.bit("Q1"));
    EXPECT_EQ(plant.value("SMW6"), 1000); // 100 ms in 100 µs
    plant.engine.memory().setBit(at("SM37.0"), true);
    plant.engine.memory().setBit(at("SM0.5"), true);
    plant.scans(1);
    EXPECT_TRUE(plant.bit("Q3"));
}

TEST(Pl110Scan, MarksWhatEachElementOfEachRungDid) {
    Plant plant("INIT\n(VW1 = 1)\nMAIN\nQ1 = I1 * /I2 + NOT\nTON(T1, 10ms, 5) = I3\n");
    plant.set("I1", true);
    plant.scans(1);
    ASSERT_EQ(plant.engine.marks().size(), 3U);
    EXPECT_TRUE(plant.engine.marks()[0].ran); // INIT's rung in the first scan
    const RungMarks& coil = plant.engine.marks()[1];
    // 0 the output, 1 the OR, 2 the AND, 3 I1, 4 /I2, 5 NOT.
    EXPECT_EQ(coil.power, (std::vector<std::uint8_t>{1, 1, 1, 1, 1, 0}));
    EXPECT_EQ(coil.states[3], sim::ElementState::Closed);
    EXPECT_EQ(coil.states[0], sim::ElementState::Closed); // Q1 is 1
    plant.set("I2", true);
    plant.set("I3", true);
    plant.scans(1);
    EXPECT_FALSE(plant.engine.marks()[0].ran); // INIT runs once
    EXPECT_EQ(plant.engine.marks()[1].power, (std::vector<std::uint8_t>{0, 0, 0, 1, 0, 0}));
    EXPECT_EQ(plant.engine.marks()[2].states[0], sim::ElementState::Running);
    plant.scans(5);
    EXPECT_EQ(plant.engine.marks()[2].states[0], sim::ElementState::Closed);
}

TEST(Pl110Scan, RandomCheckedProgramsRunDeterministically) {
    std::mt19937 random(4);
    for (int i = 0; i < 300; ++i) {
        const Program program = testing::randomProgram(random, true);
        ASSERT_TRUE(checkProgram(program).empty())
            << printProgram(program) << checkProgram(program).front().message;
        ScanEngine first(program);
        ScanEngine second(program);
        std::mt19937 inputs(static_cast<unsigned>(i));
        for (int scan = 0; scan < 40; ++scan) {
            const Address input{Area::Input, Width::Bit, static_cast<int>(inputs() % 8) + 1, -1};
            const bool on = inputs() % 2 == 0;
            first.memory().setBit(input, on);
            second.memory().setBit(input, on);
            first.scan();
            second.scan();
        }
        ASSERT_EQ(first.memory().words, second.memory().words) << printProgram(program);
    }
}

} // namespace
} // namespace rs::pl110
