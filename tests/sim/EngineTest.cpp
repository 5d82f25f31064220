// SPDX-License-Identifier: GPL-3.0-or-later
#include "SimulationFixture.h"

#include <gtest/gtest.h>

using rs::test::Simulated;
using rs::test::unitZero;

TEST(Engine, SeriesAndParallelContactsAndNegation) {
    Simulated s(unitZero("Q0.1 = I0.0 * (I0.1 + /I0.2)\n"));
    for (int bits = 0; bits < 8; ++bits) {
        const bool i0 = bits & 1, i1 = bits & 2, i2 = bits & 4;
        s.set("I0.0", i0);
        s.set("I0.1", i1);
        s.set("I0.2", i2);
        s.scans(1);
        EXPECT_EQ(s["Q0.1"], i0 && (i1 || !i2)) << bits;
    }
}

TEST(Engine, AnEdgeIsTrueForOneScanAndNotAtStart) {
    Simulated s(unitZero("M0.1 = P(I0.0)\nM0.2 = N(I0.0)\nM0.3 = P(/I0.0)\nM0.4 = /P(I0.0)\n"));
    s.set("I0.0", 1); // held while the system starts: not a press
    s.scans(1);
    EXPECT_EQ(s["M0.1"], 0);
    EXPECT_EQ(s["M0.4"], 1);
    s.set("I0.0", 0);
    s.scans(1);
    EXPECT_EQ(s["M0.2"], 1);
    EXPECT_EQ(s["M0.3"], 1);
    s.scans(1);
    EXPECT_EQ(s["M0.2"], 0);
    s.set("I0.0", 1);
    s.scans(1);
    EXPECT_EQ(s["M0.1"], 1);
    EXPECT_EQ(s["M0.4"], 0);
    s.scans(1);
    EXPECT_EQ(s["M0.1"], 0);
    EXPECT_EQ(s["M0.4"], 1);
}

TEST(Engine, OnDelayTimerNeedsItsInputForThePresetAndIgnoresWhatIsRightOfIt) {
    // The manual: Q0.11 = I0.3 * TON(2s5) * I0.0; I0.0 has no influence on the timer.
    Simulated s(unitZero("Q0.11 = I0.3 * TON(2s5) * I0.0\nM0.1 = I0.3 * TON(0s10)\n"));
    s.set("I0.3", 1);
    s.scans(250); // input true for 2.49 s
    EXPECT_EQ(s["Q0.11"], 0);
    s.set("I0.0", 1);
    s.scans(1);
    EXPECT_EQ(s["Q0.11"], 1);
    s.set("I0.3", 0);
    s.scans(1);
    EXPECT_EQ(s["Q0.11"], 0);
    s.set("I0.3", 1);
    s.scans(10);
    EXPECT_EQ(s["M0.1"], 0);
    s.scans(1);
    EXPECT_EQ(s["M0.1"], 1);
}

TEST(Engine, PulseTimerIsTrueFromTheRiseForThePreset) {
    Simulated s(unitZero("Q0.12 = I0.4 * TPS(3s5)\n"));
    s.set("I0.4", 1);
    s.scans(1);
    EXPECT_EQ(s["Q0.12"], 1);
    s.scans(349);
    EXPECT_EQ(s["Q0.12"], 1); // 3.49 s
    s.scans(1);
    EXPECT_EQ(s["Q0.12"], 0);
    s.set("I0.4", 0);
    s.scans(1);
    s.set("I0.4", 1);
    s.scans(10);
    s.set("I0.4", 0); // the input falling ends the pulse early
    s.scans(1);
    EXPECT_EQ(s["Q0.12"], 0);
}

TEST(Engine, NegatedOnDelayTimerGivesAPulse) {
    Simulated s(unitZero("Q0.12 = I0.4 * /TON(2s5)\n"));
    s.set("I0.4", 1);
    s.scans(1);
    EXPECT_EQ(s["Q0.12"], 1);
    s.scans(249);
    EXPECT_EQ(s["Q0.12"], 1);
    s.scans(1);
    EXPECT_EQ(s["Q0.12"], 0);
}

TEST(Engine, OffDelayTimerFollowsUpAndFallsAfterThePreset) {
    Simulated s(unitZero("Q0.13 = I0.5 * TOF(1s00)\n"));
    s.scans(1);
    EXPECT_EQ(s["Q0.13"], 0);
    s.set("I0.5", 1);
    s.scans(1);
    EXPECT_EQ(s["Q0.13"], 1);
    s.set("I0.5", 0);
    s.scans(100);
    EXPECT_EQ(s["Q0.13"], 1); // false for 0.99 s
    s.scans(1);
    EXPECT_EQ(s["Q0.13"], 0);
}

TEST(Engine, TimerPresetFromARegisterInHundredths) {
    Simulated s(unitZero("(R0.5 = 20)\nM0.1 = I0.0 * TON(R0.5)\n"));
    s.set("I0.0", 1);
    s.scans(20);
    EXPECT_EQ(s["M0.1"], 0);
    s.scans(1);
    EXPECT_EQ(s["M0.1"], 1);
}

TEST(Engine, LatchesKeepTheirValueAndTheLaterLineWins) {
    Simulated latch("! id_pluto:05=000000000000\n! pgm_pluto:05\nS5.0_0\n"
                    "S(Q5.17) = I5.2\nR(Q5.17) = I5.3\n");
    latch.set("I5.2", 1);
    latch.scans(1);
    latch.set("I5.2", 0);
    latch.scans(5);
    EXPECT_EQ(latch["Q5.17"], 1);
    latch.set("I5.2", 1);
    latch.set("I5.3", 1);
    latch.scans(1);
    EXPECT_EQ(latch["Q5.17"], 0); // both true: the reset, written later, decides
}

TEST(Engine, ToggleOnAnEdge) {
    Simulated s("! id_pluto:04=000000000000\n! pgm_pluto:04\nS4.0_0\nT(Q4.2) = P(I4.1)\n");
    s.scans(1);
    for (int press = 1; press <= 3; ++press) {
        s.set("I4.1", 1);
        s.scans(3);
        s.set("I4.1", 0);
        s.scans(3);
        EXPECT_EQ(s["Q4.2"], press % 2);
    }
}

TEST(Engine, JumpsTakeEffectAtTheEndOfTheSequenceAndResetTheCoilsOfTheStepLeft) {
    Simulated s(unitZero("M0.9 = M0.8\n", "S0.1_0\nM0.1\nS(M0.2) = I0.0\nJ(+1) = I0.0\n"
                                          "S0.1_1\nM0.3 = SM0.0\nM0.4\nJ(0) = I0.1\nJ(5) = I0.1\n"
                                          "S0.1_5\nM0.5\n"));
    s.scans(1);
    EXPECT_EQ(s["S0.1"], 0);
    EXPECT_EQ(s["M0.1"], 1);
    s.set("I0.0", 1);
    s.scans(1);
    EXPECT_EQ(s["S0.1"], 1);
    EXPECT_EQ(s["M0.1"], 0); // a coil of the step left
    EXPECT_EQ(s["M0.2"], 1); // a latch keeps its value
    s.set("I0.0", 0);
    s.scans(1);
    EXPECT_EQ(s["M0.3"], 1); // SM_StepNew in the first scan of the step
    EXPECT_EQ(s["M0.4"], 1);
    s.scans(1);
    EXPECT_EQ(s["M0.3"], 0);
    s.set("I0.1", 1); // two jumps true: the last in the step wins
    s.scans(1);
    EXPECT_EQ(s["S0.1"], 5);
    EXPECT_EQ(s["M0.4"], 0);
}

TEST(Engine, SequenceResetHoldsStepZero) {
    Simulated s(unitZero("R(S0.1) = I0.7\n", "S0.1_0\nJ(1) = I0.0\nS0.1_1\nM0.1\nJ(0) = M0.9\n"));
    s.set("I0.0", 1);
    s.scans(2);
    EXPECT_EQ(s["S0.1"], 1);
    s.set("I0.7", 1);
    s.scans(3);
    EXPECT_EQ(s["S0.1"], 0);
    EXPECT_EQ(s["M0.1"], 0);
    s.set("I0.7", 0);
    s.scans(1);
    EXPECT_EQ(s["S0.1"], 1);
}

TEST(Engine, ATimerInAStepThatDoesNotRunStartsAfresh) {
    Simulated s(unitZero("", "S0.1_0\nJ(1) = I0.0\nS0.1_1\nM0.1 = TON(0s50)\nJ(0) = I0.1\n"));
    s.set("I0.0", 1);
    s.scans(1);
    s.set("I0.0", 0);
    s.scans(30);
    s.set("I0.1", 1);
    s.scans(1);
    s.set("I0.1", 0);
    s.set("I0.0", 1);
    s.scans(1);
    s.set("I0.0", 0);
    s.scans(40); // 0.4 s in the step again: not yet
    EXPECT_EQ(s["M0.1"], 0);
    s.scans(11);
    EXPECT_EQ(s["M0.1"], 1);
}

TEST(Engine, RegistersSaturateAndSetTheFlags) {
    Simulated s(unitZero("(R0.1 = 32766)\n(R0.1 += 5) = I0.0\nM0.1 = SM0.11\n"
                         "(R0.2 = 7)\n(R0.2 /= R0.3) = I0.1\nM0.2 = SM0.12\n"
                         "(R0.4 = 17)\n(R0.5 = R0.4 / 5) = I0.2\n(R0.6 = SR0.2)\n"
                         "(DR0.10 = 2147483000)\n(DR0.10 += 1000) = I0.3\n"
                         "(R0.7 = -32768)\n(R0.7--) = I0.4\n"));
    s.set("I0.0", 1);
    s.scans(1);
    EXPECT_EQ(s["R0.1"], 32767);
    EXPECT_EQ(s["M0.1"], 1);
    s.set("I0.1", 1);
    s.scans(1);
    EXPECT_EQ(s["R0.2"], 0);
    EXPECT_EQ(s["M0.2"], 1);
    s.set("I0.2", 1);
    s.scans(2);
    EXPECT_EQ(s["R0.5"], 3);
    EXPECT_EQ(s["R0.6"], 2); // SR_Remain
    s.set("I0.3", 1);
    s.scans(1);
    EXPECT_EQ(s["DR0.10"], 2147483647);
    s.set("I0.4", 1);
    s.scans(1);
    EXPECT_EQ(s["R0.7"], -32768);
}

TEST(Engine, RegisterBitsAndDoubleRegisterHalves) {
    // The manual's example: bits 0 and 1 of R0.100 set give 3.
    Simulated s(unitZero("S(R0.100.0) = I0.0\nS(R0.100.1) = I0.0\nM0.1 = R0.100.1\n"
                         "(DR0.20 = 65538)\n(R0.30 = DR0.20.Hi)\n(R0.31 = DR0.20.Lo)\n"));
    s.set("I0.0", 1);
    s.scans(2);
    EXPECT_EQ(s["R0.100"], 3);
    EXPECT_EQ(s["M0.1"], 1);
    EXPECT_EQ(s["R0.30"], 1);
    EXPECT_EQ(s["R0.31"], 2);
}

TEST(Engine, SystemInitAndFlashingMemoriesFollowVirtualTime) {
    Simulated s(unitZero("M0.1 = SM0.9\nM0.2 = SM0.3\nM0.3 = SM0.2\n"));
    s.scans(1);
    EXPECT_EQ(s["M0.1"], 1);
    EXPECT_EQ(s["M0.2"], 1); // 1 Hz: on for 0..499 ms
    s.scans(1);
    EXPECT_EQ(s["M0.1"], 0);
    s.scans(38); // the scan at 390 ms
    EXPECT_EQ(s["M0.3"], 1);
    s.scans(1); // 400 ms: the flash is off
    EXPECT_EQ(s["M0.3"], 0);
    s.scans(10); // 500 ms
    EXPECT_EQ(s["M0.2"], 0);
}

TEST(Engine, MeasuredValuesAreSetLikeInputs) {
    Simulated s(unitZero("Q0.12 = (SR0.40 < 180) * SM0.5\nM0.1 = (SR0.40 = 240)\n"));
    s.scans(1);
    EXPECT_EQ(s["M0.1"], 1); // 24.0 V at power on
    s.set("SR0.40", 170);
    s.scans(1);
    EXPECT_EQ(s["Q0.12"], 1); // SM_FastFlash is on in the first 170 ms
}

TEST(Engine, ForcingOverridesTheProgramUntilReleased) {
    Simulated s(unitZero("Q0.1 = I0.0\n(R0.1 = 5)\n"));
    s.simulation->force(Simulated::at("Q0.1"), 1);
    s.simulation->force(Simulated::at("R0.1"), 9);
    s.scans(2);
    EXPECT_EQ(s["Q0.1"], 1);
    EXPECT_EQ(s["R0.1"], 9);
    s.simulation->release(Simulated::at("Q0.1"));
    s.simulation->release(Simulated::at("R0.1"));
    s.scans(1);
    EXPECT_EQ(s["Q0.1"], 0);
    EXPECT_EQ(s["R0.1"], 5);
}

TEST(Engine, UnitsSeeEachOthersGlobalsAfterTheirScan) {
    Simulated s(
        "! id_pluto:00=000000000000\n! id_pluto:01=000000000000\n"
        "! pgm_pluto:00\nS0.0_0\nQ0.2 = I0.0\nGM0.3 = I0.0\nM0.1 = SM0.101\nM0.2 = SM0.105\n"
        "! pgm_pluto:01\nS1.0_0\nM1.1 = Q0.2 * GM0.3 * I0.0\n");
    s.set("I0.0", 1);
    s.scans(1);
    EXPECT_EQ(s["Q0.2"], 1);
    EXPECT_EQ(s["M1.1"], 0); // unit 0's outputs reach unit 1 on the next scan
    s.scans(1);
    EXPECT_EQ(s["M1.1"], 1);
    EXPECT_EQ(s["M0.1"], 1); // SM_Pluto1_Present
    EXPECT_EQ(s["M0.2"], 0);
}

TEST(Engine, RestartKeepsOnlyTheRemanentVariables) {
    Simulated s(unitZero("(R0.100 = 42)\n(R0.1 = 7)\nS(M0.100) = SM0.9\n"));
    s.scans(1);
    s.simulation->setRemanent(0, {Simulated::at("R0.100"), Simulated::at("M0.100")});
    s.simulation->restart();
    EXPECT_EQ(s["R0.100"], 42);
    EXPECT_EQ(s["M0.100"], 1);
    EXPECT_EQ(s["R0.1"], 0);
    EXPECT_EQ(s.simulation->timeMs(), 0);
}

TEST(Engine, EachInstructionReportsWhetherItConducted) {
    Simulated s(unitZero("Q0.1 = I0.0 * I0.1\n", "S0.1_0\nM0.1 = I0.0\n"
                                                 "J(1) = M0.9\nS0.1_1\nM0.2 = I0.0\n"));
    s.set("I0.0", 1);
    s.scans(1);
    const auto* unit = s.simulation->unit(0);
    const auto& code = unit->image().code;
    const auto& conduction = unit->conduction();
    ASSERT_EQ(code.size(), conduction.size());
    using rs::sim::Conduction;
    // Q0.1 = I0.0 * I0.1: rung, I0.0 conducts, I0.1 does not, the coil is off.
    EXPECT_EQ(conduction[0], Conduction::On);
    EXPECT_EQ(conduction[1], Conduction::On);
    EXPECT_EQ(conduction[2], Conduction::Off);
    EXPECT_EQ(conduction[3], Conduction::Off);
    // Step 1 of sequence 1 is not active: its instructions did not run.
    EXPECT_EQ(conduction.back(), Conduction::NotRun);
}
