// SPDX-License-Identifier: GPL-3.0-or-later
#include "SafetyBench.h"

#include <gtest/gtest.h>

// SF_MutingSeq of Rungsmith_Safety walked through every state and transition
// of the public model's state machine (docs/safety-blocks.md). Aopd is the
// light curtain (on: free); M11 and M12 are the sensors before it, M21 and
// M22 those after it (on: actuated). MaxMutingTime is 0s20. DiagCodes read as
// signed registers: 16#8000 -32768, 16#8001 -32767, 16#8002 -32766,
// 16#8003 -32765, 16#8005 -32763, 16#8011 -32751, 16#8012 -32750,
// 16#8112 -32494, 16#8122 -32478, 16#C001 -16383, 16#C002 -16382,
// 16#C003 -16381, 16#C004 -16380, 16#C006 -16378, 16#C104 -16124.

using rs::safetytest::holdsOnBothInstructionSets;

namespace {

::testing::AssertionResult seqHolds(const std::string& bindings, const std::string& scenario) {
    const std::string names = "! I0.0=Act\n! I0.1=Aopd\n! I0.2=M11\n! I0.3=M12\n! I0.4=M21\n"
                              "! I0.5=M22\n! I0.6=Lamp\n! I0.7=Enable\n! I0.10=ResetButton\n"
                              "! I0.11=StartReset\n! M0.0=Ready\n! M0.1=Out\n! M0.2=Muted\n"
                              "! M0.3=Error\n! R0.0=DiagCode\n";
    const std::string record =
        ";@block SF_MutingSeq S_AOPD_In=\"Aopd\" MutingSwitch11=\"M11\" MutingSwitch12=\"M12\" "
        "MutingSwitch21=\"M21\" MutingSwitch22=\"M22\" S_MutingLamp=\"Lamp\" "
        "MaxMutingTime=\"0s20\" Ready=\"Ready\" S_AOPD_Out=\"Out\" S_MutingActive=\"Muted\" "
        "Error=\"Error\" DiagCode=\"DiagCode\" " +
        bindings + "\n;@end\n";
    return holdsOnBothInstructionSets(names, record, scenario);
}

const std::string kSequencePins = "MutingEnable=\"Enable\" Reset=\"ResetButton\"";

// From activation to 8000: the curtain free and acknowledged, the lamp good.
const std::string kSequenceToFree = R"(
set Aopd 1
set Lamp 1
scans 1
expect DiagCode -32767
set ResetButton 1
scans 1
expect DiagCode -32763
set ResetButton 0
scans 1
expect DiagCode -32768
expect Out 1
)";

// Forward: 11 rising (8011), then 12 rising (8012, muted).
const std::string kToForwardStart = kSequenceToFree + R"(
set Enable 1
set M11 1
scans 1
expect DiagCode -32751
)";
const std::string kToForwardMuted = kToForwardStart + R"(
set M12 1
scans 1
expect DiagCode -32750
expect Muted 1
)";

// Reverse: 22 rising (8122), then 21 rising (8112, muted).
const std::string kToReverseStart = kSequenceToFree + R"(
set Enable 1
set M22 1
scans 1
expect DiagCode -32478
)";
const std::string kToReverseMuted = kToReverseStart + R"(
set M21 1
scans 1
expect DiagCode -32494
expect Muted 1
)";

} // namespace

TEST(SF_MutingSeq, ActivateOffHoldsStateZeroWithEveryOutputOff) {
    EXPECT_TRUE(seqHolds(kSequencePins + " Activate=\"Act\"", R"(
set Aopd 1
set Lamp 1
scans 2
expect DiagCode 0
expect Ready 0
expect Out 0
expect Muted 0
expect Error 0
set Act 1
scans 1
# the first active scan: 0000 -> 8001
expect DiagCode -32767
expect Ready 1
expect Out 0
set ResetButton 1
scans 2
set ResetButton 0
set Enable 1
set M11 1
scans 1
set M12 1
scans 1
expect DiagCode -32750
expect Muted 1
set Act 0
scans 1
expect DiagCode 0
expect Ready 0
expect Out 0
expect Muted 0
# Activate off also leaves an error state: M12 on in 8000 is C004
set Act 1
scans 1
set ResetButton 1
scans 3
expect DiagCode -16380
expect Error 1
set Act 0
scans 1
expect DiagCode 0
expect Error 0
)"));
}

TEST(SF_MutingSeq, OpenInputsMeanActiveNoAcknowledgementAndNoMuting) {
    EXPECT_TRUE(seqHolds("", R"(
set Aopd 1
set Lamp 1
scans 1
expect DiagCode -32767
expect Ready 1
expect Out 0
run 1s
expect DiagCode -32767
)"));
    // MutingEnable open is 0: 11 rising is a wrong sequence
    EXPECT_TRUE(seqHolds("Reset=\"ResetButton\"", kSequenceToFree + R"(
set M11 1
scans 1
expect DiagCode -16380
)"));
}

TEST(SF_MutingSeq, StartResetAcknowledgesAtStartAndMakesAHeldResetNoError) {
    EXPECT_TRUE(seqHolds(kSequencePins + " S_StartReset=\"StartReset\"", R"(
set StartReset 1
set ResetButton 1
set Aopd 1
set Lamp 1
scans 1
expect DiagCode -32767
scans 1
expect DiagCode -32763
scans 1
expect DiagCode -32768
expect Error 0
)"));
}

TEST(SF_MutingSeq, AResetHeldAtStartIsC001LeftByReleasingIt) {
    EXPECT_TRUE(seqHolds(kSequencePins, R"(
set ResetButton 1
set Aopd 1
set Lamp 1
scans 1
expect DiagCode -32767
scans 1
expect DiagCode -16383
expect Error 1
scans 3
expect DiagCode -16383
set ResetButton 0
scans 1
expect DiagCode -32767
set ResetButton 1
scans 1
expect DiagCode -32763
)"));
}

TEST(SF_MutingSeq, TheCheckAfterAPressGoesTo8002WithTheCurtainInterruptedOrC003WithoutLamp) {
    EXPECT_TRUE(seqHolds(kSequencePins, R"(
set Lamp 1
scans 1
set ResetButton 1
scans 1
expect DiagCode -32763
scans 1
expect DiagCode -32766
expect Out 0
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, R"(
set Aopd 1
scans 1
set ResetButton 1
scans 1
scans 1
expect DiagCode -16381
expect Error 1
set Lamp 1
scans 1
expect DiagCode -32765
expect Error 0
)"));
}

TEST(SF_MutingSeq, AnInterruptedCurtainSwitchesOffAndNeedsAPressOnceFree) {
    EXPECT_TRUE(seqHolds(kSequencePins, kSequenceToFree + R"(
set Aopd 0
scans 1
expect DiagCode -32766
expect Out 0
set Aopd 1
scans 1
expect DiagCode -32765
scans 3
expect DiagCode -32765
set ResetButton 1
scans 1
expect DiagCode -32763
scans 1
expect DiagCode -32768
)"));
    // a Reset held when 8003 is reached is C002 until released
    EXPECT_TRUE(seqHolds(kSequencePins, kSequenceToFree + R"(
set Aopd 0
set ResetButton 1
scans 1
set Aopd 1
scans 1
expect DiagCode -32765
scans 1
expect DiagCode -16382
expect Error 1
scans 2
expect DiagCode -16382
set ResetButton 0
scans 1
expect DiagCode -32765
)"));
}

TEST(SF_MutingSeq, AFaultyLampWhileFreeIsC003) {
    EXPECT_TRUE(seqHolds(kSequencePins, kSequenceToFree + R"(
set Lamp 0
scans 1
expect DiagCode -16381
expect Out 0
)"));
}

TEST(SF_MutingSeq, ASensorOutOfSequenceWhileFreeIsC004LeftWithEverySensorFree) {
    // 11 or 22 rising without MutingEnable
    EXPECT_TRUE(seqHolds(kSequencePins, kSequenceToFree + R"(
set M11 1
scans 1
expect DiagCode -16380
expect Error 1
expect Out 0
scans 3
expect DiagCode -16380
set M11 0
scans 1
expect DiagCode -32765
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kSequenceToFree + R"(
set M22 1
scans 1
expect DiagCode -16380
set M22 0
scans 1
expect DiagCode -32765
)"));
    // an inner sensor, even with MutingEnable
    EXPECT_TRUE(seqHolds(kSequencePins, kSequenceToFree + R"(
set Enable 1
set M12 1
scans 1
expect DiagCode -16380
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kSequenceToFree + R"(
set Enable 1
set M21 1
scans 1
expect DiagCode -16380
)"));
    // both outer sensors at once, with MutingEnable
    EXPECT_TRUE(seqHolds(kSequencePins, kSequenceToFree + R"(
set Enable 1
set M11 1
set M22 1
scans 1
expect DiagCode -16380
set M11 0
scans 1
expect DiagCode -16380
set M22 0
scans 1
expect DiagCode -32765
)"));
}

TEST(SF_MutingSeq, AForwardPassageMutesFrom12RisingTo21Falling) {
    EXPECT_TRUE(seqHolds(kSequencePins, kToForwardStart + R"(
expect Out 1
expect Muted 0
set M12 1
scans 1
expect DiagCode -32750
expect Out 1
expect Muted 1
set Enable 0
set Aopd 0
scans 1
set M21 1
scans 1
set M22 1
scans 1
set M11 0
scans 1
set M12 0
scans 1
set Aopd 1
scans 1
expect DiagCode -32750
expect Out 1
set M21 0
scans 1
expect DiagCode -32768
expect Out 1
expect Muted 0
set M22 0
scans 3
expect DiagCode -32768
)"));
}

TEST(SF_MutingSeq, AReversePassageMutesFrom21RisingTo12Falling) {
    EXPECT_TRUE(seqHolds(kSequencePins, kToReverseStart + R"(
expect Out 1
expect Muted 0
set M21 1
scans 1
expect DiagCode -32494
expect Muted 1
set Enable 0
set Aopd 0
set M12 1
scans 1
set M11 1
scans 1
set M22 0
scans 1
set M21 0
scans 1
set Aopd 1
scans 1
expect DiagCode -32494
set M12 0
scans 1
expect DiagCode -32768
expect Muted 0
)"));
}

TEST(SF_MutingSeq, LeavingTheForwardStartOutOfSequenceIsC104) {
    EXPECT_TRUE(seqHolds(kSequencePins, kToForwardStart + R"(
set Enable 0
scans 1
expect DiagCode -16124
expect Error 1
expect Out 0
set M11 0
scans 1
expect DiagCode -32765
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToForwardStart + R"(
set M11 0
scans 1
expect DiagCode -16124
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToForwardStart + R"(
set M21 1
scans 1
expect DiagCode -16124
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToForwardStart + R"(
set M22 1
scans 1
expect DiagCode -16124
set M11 0
scans 1
expect DiagCode -16124
set M22 0
scans 1
expect DiagCode -32765
)"));
}

TEST(SF_MutingSeq, TheCurtainOrTheLampLostBeforeMutingLeavesTheStart) {
    EXPECT_TRUE(seqHolds(kSequencePins, kToForwardStart + R"(
set Aopd 0
scans 1
expect DiagCode -32766
expect Out 0
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToForwardStart + R"(
set Lamp 0
scans 1
expect DiagCode -16381
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToReverseStart + R"(
set Aopd 0
scans 1
expect DiagCode -32766
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToReverseStart + R"(
set Lamp 0
scans 1
expect DiagCode -16381
)"));
}

TEST(SF_MutingSeq, WhileMutedForwardARisingFrontSensorOrA22FallingIsC104) {
    EXPECT_TRUE(seqHolds(kSequencePins, kToForwardMuted + R"(
set M11 0
scans 1
expect DiagCode -32750
set M11 1
scans 1
expect DiagCode -16124
expect Muted 0
expect Out 0
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToForwardMuted + R"(
set M12 0
scans 1
expect DiagCode -32750
set M12 1
scans 1
expect DiagCode -16124
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToForwardMuted + R"(
set M22 1
scans 1
expect DiagCode -32750
set M22 0
scans 1
expect DiagCode -16124
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToForwardMuted + R"(
set Lamp 0
scans 1
expect DiagCode -16381
expect Out 0
)"));
}

TEST(SF_MutingSeq, LeavingTheReverseStartOutOfSequenceIsC104) {
    EXPECT_TRUE(seqHolds(kSequencePins, kToReverseStart + R"(
set Enable 0
scans 1
expect DiagCode -16124
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToReverseStart + R"(
set M11 1
scans 1
expect DiagCode -16124
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToReverseStart + R"(
set M12 1
scans 1
expect DiagCode -16124
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToReverseStart + R"(
set M22 0
scans 1
expect DiagCode -16124
)"));
}

TEST(SF_MutingSeq, WhileMutedInReverseA11FallingOrARisingRearSensorIsC104) {
    EXPECT_TRUE(seqHolds(kSequencePins, kToReverseMuted + R"(
set M11 1
scans 1
expect DiagCode -32494
set M11 0
scans 1
expect DiagCode -16124
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToReverseMuted + R"(
set M21 0
scans 1
expect DiagCode -32494
set M21 1
scans 1
expect DiagCode -16124
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToReverseMuted + R"(
set M22 0
scans 1
expect DiagCode -32494
set M22 1
scans 1
expect DiagCode -16124
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToReverseMuted + R"(
set Lamp 0
scans 1
expect DiagCode -16381
)"));
}

TEST(SF_MutingSeq, APassageEndingExactlyMaxMutingTimeAfterItsStartPassesAndOneScanLaterFails) {
    // 8011 entered in scan k: the passage ended in scan k + 20 passes.
    EXPECT_TRUE(seqHolds(kSequencePins, kToForwardMuted + R"(
set M21 1
set M22 1
scans 1
set M11 0
set M12 0
scans 17
expect DiagCode -32750
set M21 0
scans 1
expect DiagCode -32768
expect Error 0
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToForwardMuted + R"(
scans 19
expect DiagCode -32750
scans 1
expect DiagCode -16378
expect Error 1
expect Out 0
expect Muted 0
set M11 0
set M12 0
scans 1
expect DiagCode -32765
)"));
}

TEST(SF_MutingSeq, MaxMutingTimeRunsOutInEachSequenceState) {
    EXPECT_TRUE(seqHolds(kSequencePins, kToForwardStart + R"(
scans 20
expect DiagCode -32751
scans 1
expect DiagCode -16378
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToReverseStart + R"(
scans 20
expect DiagCode -32478
scans 1
expect DiagCode -16378
)"));
    EXPECT_TRUE(seqHolds(kSequencePins, kToReverseMuted + R"(
scans 19
expect DiagCode -32494
scans 1
expect DiagCode -16378
)"));
}

TEST(SF_MutingSeq, EveryPassageTimesAfresh) {
    EXPECT_TRUE(seqHolds(kSequencePins, kToForwardMuted + R"(
set M21 1
set M22 1
set M11 0
set M12 0
scans 10
set M21 0
scans 1
expect DiagCode -32768
set M22 0
scans 1
set M11 1
scans 1
expect DiagCode -32751
set M12 1
scans 19
expect DiagCode -32750
)"));
}
