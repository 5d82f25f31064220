// SPDX-License-Identifier: GPL-3.0-or-later
#include "SafetyBench.h"

#include <gtest/gtest.h>

// SF_MutingPar_2Sensor of Rungsmith_Safety walked through every state and
// transition of the state machine written down in docs/safety-blocks.md
// (Rungsmith's reading of the public descriptions). Aopd is the light
// curtain (on: free), S11 and S12 the muting sensors (on: actuated by the
// workpiece). DiscTimeEntry is 0s05 and MaxMutingTime 0s20 unless a test
// says otherwise. DiagCodes read as signed registers: 16#8000 -32768,
// 16#8001 -32767, 16#8002 -32766, 16#8003 -32765, 16#8005 -32763,
// 16#8011 -32751, 16#8012 -32750, 16#8021 -32735, 16#C001 -16383,
// 16#C002 -16382, 16#C003 -16381, 16#C004 -16380, 16#C006 -16378,
// 16#C007 -16377.

using rs::safetytest::holdsOnBothInstructionSets;

namespace {

::testing::AssertionResult mutingHolds(const std::string& bindings, const std::string& scenario) {
    const std::string names = "! I0.0=Act\n! I0.1=Aopd\n! I0.2=S11\n! I0.3=S12\n! I0.4=Lamp\n"
                              "! I0.5=Enable\n! I0.6=ResetButton\n! I0.7=StartReset\n"
                              "! M0.0=Ready\n! M0.1=Out\n! M0.2=Muted\n! M0.3=Error\n"
                              "! R0.0=DiagCode\n";
    const std::string record =
        ";@block SF_MutingPar_2Sensor S_AOPD_In=\"Aopd\" S_MutingSwitch11=\"S11\" "
        "S_MutingSwitch12=\"S12\" S_MutingLamp=\"Lamp\" Ready=\"Ready\" S_AOPD_Out=\"Out\" "
        "S_MutingActive=\"Muted\" Error=\"Error\" DiagCode=\"DiagCode\" " +
        bindings + "\n;@end\n";
    return holdsOnBothInstructionSets(names, record, scenario);
}

const std::string kTimes = "DiscTimeEntry=\"0s05\" MaxMutingTime=\"0s20\" ";
const std::string kParallelPins = kTimes + "MutingEnable=\"Enable\" Reset=\"ResetButton\"";

// From activation to 8000: the curtain free and acknowledged, the lamp good.
const std::string kParallelToFree = R"(
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

// From 8000 to 8011: MutingEnable and S11 rising.
const std::string kToEntry11 = kParallelToFree + R"(
set Enable 1
set S11 1
scans 1
expect DiagCode -32751
)";

// From 8000 to 8021: MutingEnable and S12 rising.
const std::string kToEntry12 = kParallelToFree + R"(
set Enable 1
set S12 1
scans 1
expect DiagCode -32735
)";

// From 8011 to 8012: muted.
const std::string kToMuted = kToEntry11 + R"(
set S12 1
scans 1
expect DiagCode -32750
expect Muted 1
)";

} // namespace

TEST(SF_MutingPar_2Sensor, ActivateOffHoldsStateZeroWithEveryOutputOff) {
    EXPECT_TRUE(mutingHolds(kParallelPins + " Activate=\"Act\"", R"(
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
expect DiagCode -32768
set Enable 1
set S11 1
set S12 1
scans 1
expect DiagCode -32750
expect Muted 1
set Act 0
scans 1
expect DiagCode 0
expect Ready 0
expect Out 0
expect Muted 0
# Activate off also leaves an error state
set Enable 0
set S11 0
set S12 0
set Act 1
scans 1
set ResetButton 1
scans 2
set S11 1
scans 1
expect DiagCode -16380
expect Error 1
set Act 0
scans 1
expect DiagCode 0
expect Error 0
)"));
}

TEST(SF_MutingPar_2Sensor, OpenInputsMeanActiveNoAcknowledgementAndNoMuting) {
    EXPECT_TRUE(mutingHolds(kTimes, R"(
set Aopd 1
set Lamp 1
scans 1
expect DiagCode -32767
expect Ready 1
expect Out 0
run 1s
expect DiagCode -32767
expect Out 0
)"));
    // MutingEnable open is 0: a sensor rising is a wrong sequence
    EXPECT_TRUE(mutingHolds(kTimes + "Reset=\"ResetButton\"", kParallelToFree + R"(
set S12 1
scans 1
expect DiagCode -16380
)"));
}

TEST(SF_MutingPar_2Sensor, StartResetAcknowledgesAtStartAndMakesAHeldResetNoError) {
    EXPECT_TRUE(mutingHolds(kParallelPins + " S_StartReset=\"StartReset\"", R"(
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

TEST(SF_MutingPar_2Sensor, AResetHeldAtStartIsC001LeftByReleasingIt) {
    EXPECT_TRUE(mutingHolds(kParallelPins, R"(
set ResetButton 1
set Aopd 1
set Lamp 1
scans 1
expect DiagCode -32767
scans 1
expect DiagCode -16383
expect Error 1
expect Out 0
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

TEST(SF_MutingPar_2Sensor,
     TheCheckAfterAPressGoesTo8002WithTheCurtainInterruptedOrC003WithoutLamp) {
    EXPECT_TRUE(mutingHolds(kParallelPins, R"(
set Lamp 1
scans 1
set ResetButton 1
scans 1
expect DiagCode -32763
scans 1
expect DiagCode -32766
expect Out 0
)"));
    EXPECT_TRUE(mutingHolds(kParallelPins, R"(
set Aopd 1
scans 1
set ResetButton 1
scans 1
expect DiagCode -32763
scans 1
expect DiagCode -16381
expect Error 1
set Lamp 1
scans 1
expect DiagCode -32765
expect Error 0
set ResetButton 0
scans 1
set ResetButton 1
scans 1
expect DiagCode -32763
scans 1
expect DiagCode -32768
)"));
}

TEST(SF_MutingPar_2Sensor, AnInterruptedCurtainSwitchesOffAndNeedsAPressOnceFree) {
    EXPECT_TRUE(mutingHolds(kParallelPins, kParallelToFree + R"(
expect Muted 0
expect Error 0
scans 5
expect DiagCode -32768
set Aopd 0
scans 1
expect DiagCode -32766
expect Out 0
scans 3
expect DiagCode -32766
set Aopd 1
scans 1
expect DiagCode -32765
expect Out 0
scans 3
expect DiagCode -32765
set ResetButton 1
scans 1
expect DiagCode -32763
scans 1
expect DiagCode -32768
expect Out 1
)"));
}

TEST(SF_MutingPar_2Sensor, AResetHeldWhen8003IsReachedIsC002LeftByReleasingIt) {
    EXPECT_TRUE(mutingHolds(kParallelPins, kParallelToFree + R"(
set Aopd 0
set ResetButton 1
scans 1
expect DiagCode -32766
set Aopd 1
scans 1
expect DiagCode -32765
scans 1
expect DiagCode -16382
expect Error 1
scans 3
expect DiagCode -16382
set ResetButton 0
scans 1
expect DiagCode -32765
expect Error 0
)"));
}

TEST(SF_MutingPar_2Sensor, AFaultyLampWhileFreeIsC003) {
    EXPECT_TRUE(mutingHolds(kParallelPins, kParallelToFree + R"(
set Lamp 0
scans 1
expect DiagCode -16381
expect Error 1
expect Out 0
)"));
}

TEST(SF_MutingPar_2Sensor, ASensorRisingWithoutMutingEnableIsC004LeftWithBothSensorsFree) {
    EXPECT_TRUE(mutingHolds(kParallelPins, kParallelToFree + R"(
set S11 1
scans 1
expect DiagCode -16380
expect Error 1
expect Out 0
set S12 1
scans 1
set S11 0
scans 1
expect DiagCode -16380
set S12 0
scans 1
expect DiagCode -32765
expect Error 0
)"));
    EXPECT_TRUE(mutingHolds(kParallelPins, kParallelToFree + R"(
set S12 1
scans 1
expect DiagCode -16380
)"));
}

TEST(SF_MutingPar_2Sensor, S11ThenS12MutesTheCurtainUntilASensorIsFree) {
    EXPECT_TRUE(mutingHolds(kParallelPins, kToEntry11 + R"(
expect Out 1
expect Muted 0
expect Error 0
set S12 1
scans 1
expect DiagCode -32750
expect Out 1
expect Muted 1
set Enable 0
set Aopd 0
scans 5
expect DiagCode -32750
expect Out 1
set Aopd 1
set S11 0
scans 1
expect DiagCode -32768
expect Out 1
expect Muted 0
)"));
    // the muting ending with the curtain still interrupted switches off
    EXPECT_TRUE(mutingHolds(kParallelPins, kToMuted + R"(
set Aopd 0
scans 1
set S12 0
scans 1
expect DiagCode -32766
expect Out 0
expect Muted 0
)"));
}

TEST(SF_MutingPar_2Sensor, S12ThenS11MutesTheCurtainToo) {
    EXPECT_TRUE(mutingHolds(kParallelPins, kToEntry12 + R"(
expect Out 1
expect Muted 0
set S11 1
scans 1
expect DiagCode -32750
expect Muted 1
)"));
}

TEST(SF_MutingPar_2Sensor, BothSensorsRisingTogetherMuteAtOnce) {
    EXPECT_TRUE(mutingHolds(kParallelPins, kParallelToFree + R"(
set Enable 1
set S11 1
set S12 1
scans 1
expect DiagCode -32750
expect Muted 1
)"));
}

TEST(SF_MutingPar_2Sensor, ASensorRisingWhileTheOtherIsStillOnStartsNoMuting) {
    EXPECT_TRUE(mutingHolds(kParallelPins, kToMuted + R"(
set S11 0
scans 1
expect DiagCode -32768
set S11 1
scans 3
expect DiagCode -32768
expect Muted 0
)"));
}

TEST(SF_MutingPar_2Sensor, TheSecondSensorExactlyDiscTimeEntryLaterPassesAndOneScanLaterFails) {
    // 8011 entered in scan k: S12 seen in scan k + 5 mutes.
    EXPECT_TRUE(mutingHolds(kParallelPins, kToEntry11 + R"(
scans 4
set S12 1
scans 1
expect DiagCode -32750
)"));
    EXPECT_TRUE(mutingHolds(kParallelPins, kToEntry11 + R"(
scans 5
expect DiagCode -32751
set S12 1
scans 1
expect DiagCode -16377
expect Error 1
expect Out 0
set S11 0
scans 1
expect DiagCode -16377
set S12 0
scans 1
expect DiagCode -32765
)"));
    EXPECT_TRUE(mutingHolds(kParallelPins, kToEntry12 + R"(
scans 4
set S11 1
scans 1
expect DiagCode -32750
)"));
    EXPECT_TRUE(mutingHolds(kParallelPins, kToEntry12 + R"(
scans 5
expect DiagCode -32735
scans 1
expect DiagCode -16377
)"));
}

TEST(SF_MutingPar_2Sensor,
     MutingEndingExactlyMaxMutingTimeAfterTheFirstSensorPassesAndOneScanLaterFails) {
    // 8011 entered in scan k, 8012 in k + 1: a sensor free in scan k + 20
    // ends the muting.
    EXPECT_TRUE(mutingHolds(kParallelPins, kToMuted + R"(
scans 18
expect DiagCode -32750
set S12 0
scans 1
expect DiagCode -32768
expect Error 0
)"));
    EXPECT_TRUE(mutingHolds(kParallelPins, kToMuted + R"(
scans 19
expect DiagCode -32750
scans 1
expect DiagCode -16378
expect Error 1
expect Out 0
expect Muted 0
set S11 0
set S12 0
scans 1
expect DiagCode -32765
)"));
    // both rising together: 8012 entered in scan k
    EXPECT_TRUE(mutingHolds(kParallelPins, kParallelToFree + R"(
set Enable 1
set S11 1
set S12 1
scans 1
expect DiagCode -32750
scans 20
expect DiagCode -32750
scans 1
expect DiagCode -16378
)"));
}

TEST(SF_MutingPar_2Sensor, MaxMutingTimeShorterThanDiscTimeEntryEndsTheEntryInC006) {
    const std::string pins = "DiscTimeEntry=\"0s20\" MaxMutingTime=\"0s05\" "
                             "MutingEnable=\"Enable\" Reset=\"ResetButton\"";
    EXPECT_TRUE(mutingHolds(pins, kToEntry11 + R"(
scans 5
expect DiagCode -32751
scans 1
expect DiagCode -16378
)"));
    EXPECT_TRUE(mutingHolds(pins, kToEntry12 + R"(
scans 5
expect DiagCode -32735
scans 1
expect DiagCode -16378
)"));
}

TEST(SF_MutingPar_2Sensor, TheFirstSensorFreeBeforeTheSecondIsC004) {
    EXPECT_TRUE(mutingHolds(kParallelPins, kToEntry11 + R"(
set S11 0
scans 1
expect DiagCode -16380
)"));
    EXPECT_TRUE(mutingHolds(kParallelPins, kToEntry12 + R"(
set S12 0
scans 1
expect DiagCode -16380
)"));
}

TEST(SF_MutingPar_2Sensor, TheCurtainInterruptedBeforeMutingSwitchesOff) {
    EXPECT_TRUE(mutingHolds(kParallelPins, kToEntry11 + R"(
set Aopd 0
scans 1
expect DiagCode -32766
expect Out 0
)"));
    EXPECT_TRUE(mutingHolds(kParallelPins, kToEntry12 + R"(
set Aopd 0
scans 1
expect DiagCode -32766
)"));
}

TEST(SF_MutingPar_2Sensor, AFaultyLampDuringEntryOrMutingIsC003) {
    EXPECT_TRUE(mutingHolds(kParallelPins, kToEntry11 + R"(
set Lamp 0
scans 1
expect DiagCode -16381
)"));
    EXPECT_TRUE(mutingHolds(kParallelPins, kToEntry12 + R"(
set Lamp 0
scans 1
expect DiagCode -16381
)"));
    EXPECT_TRUE(mutingHolds(kParallelPins, kToMuted + R"(
set Lamp 0
set S11 0
scans 1
expect DiagCode -16381
expect Out 0
expect Muted 0
)"));
}
