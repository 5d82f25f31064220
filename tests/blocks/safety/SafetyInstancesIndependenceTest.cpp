// SPDX-License-Identifier: GPL-3.0-or-later
#include "SafetyBench.h"

#include <gtest/gtest.h>

// Instances of the safety blocks keep their own state, timer and edge:
// several in one unit, and instances in two units of one project.

using rs::safetytest::holdsOnBothInstructionSets;
using rs::safetytest::scenarioHolds;

TEST(SafetyInstances, TwoInstancesInOneUnitHaveTheirOwnStateTimerAndEdge) {
    const std::string names = "! I0.0=A1\n! I0.1=B1\n! I0.2=A2\n! I0.3=B2\n! I0.4=Stop1\n"
                              "! I0.5=Stop2\n! I0.6=Reset1\n! I0.7=Reset2\n! M0.0=Out1\n"
                              "! M0.1=Out2\n! M0.2=StopOut1\n! M0.3=StopOut2\n! R0.0=Diag1\n"
                              "! R0.1=Diag2\n! R0.2=StopDiag1\n! R0.3=StopDiag2\n";
    const std::string code =
        ";@block SF_Equivalent S_ChannelA=\"A1\" S_ChannelB=\"B1\" DiscrepancyTime=\"0s05\" "
        "S_EquivalentOut=\"Out1\" DiagCode=\"Diag1\"\n;@end\n"
        ";@block SF_Equivalent S_ChannelA=\"A2\" S_ChannelB=\"B2\" DiscrepancyTime=\"0s10\" "
        "S_EquivalentOut=\"Out2\" DiagCode=\"Diag2\"\n;@end\n"
        ";@block SF_EmergencyStop S_EStopIn=\"Stop1\" Reset=\"Reset1\" S_EStopOut=\"StopOut1\" "
        "DiagCode=\"StopDiag1\"\n;@end\n"
        ";@block SF_EmergencyStop S_EStopIn=\"Stop2\" Reset=\"Reset2\" S_EStopOut=\"StopOut2\" "
        "DiagCode=\"StopDiag2\"\n;@end\n";
    EXPECT_TRUE(holdsOnBothInstructionSets(names, code, R"(
scans 1
set A1 1
scans 1
expect Diag1 -32764
expect Diag2 -32767
run 30ms
set A2 1
scans 1
expect Diag2 -32764
# the first instance's 50 ms run out, the second's 100 ms do not
run 30ms
expect Diag1 -16383
expect Diag2 -32764
set B2 1
scans 1
expect Diag2 -32768
expect Out2 1
expect Diag1 -16383
expect Out1 0
# each stop sees its own reset button
set Stop1 1
set Stop2 1
scans 1
expect StopDiag1 -32765
expect StopDiag2 -32765
set Reset1 1
scans 1
expect StopDiag1 -32768
expect StopOut1 1
expect StopDiag2 -32765
expect StopOut2 0
set Reset2 1
scans 1
expect StopDiag2 -32768
expect StopDiag1 -32768
)"));
}

TEST(SafetyInstances, InstancesInTwoUnitsOfOneProjectAreIndependent) {
    // Unit 0 an A20 with instruction set 3, unit 1 a B46 with set 2; each
    // instance takes its private variables from its own unit.
    const std::string project = "! id_pluto:00=000000000000\n! type_pluto:00=A20,is3\n"
                                "! id_pluto_Double:01=000000000001\n! type_pluto:01=B46,is2\n"
                                "! pgm_pluto:00\nS0.0_0\n"
                                ";@block SF_Equivalent S_ChannelA=\"I0.0\" S_ChannelB=\"I0.1\" "
                                "DiscrepancyTime=\"0s05\" S_EquivalentOut=\"M0.0\" "
                                "DiagCode=\"R0.0\"\n;@end\n"
                                "! pgm_pluto:01\nS1.0_0\n"
                                ";@block SF_Equivalent S_ChannelA=\"I1.0\" S_ChannelB=\"I1.1\" "
                                "DiscrepancyTime=\"0s05\" S_EquivalentOut=\"M1.0\" "
                                "DiagCode=\"R1.0\"\n;@end\n";
    EXPECT_TRUE(scenarioHolds(project, R"(
scans 1
set I0.0 1
set I1.0 1
set I1.1 1
scans 1
expect R0.0 -32764
expect R1.0 -32768
expect M1.0 1
run 60ms
expect R0.0 -16383
expect M0.0 0
expect R1.0 -32768
expect M1.0 1
set I1.0 0
set I1.1 0
scans 1
expect R1.0 -32767
expect R0.0 -16383
)"));
}

TEST(SafetyInstances, TwoHandControlsAndGuardLocksInOneUnitHaveTheirOwnTimerAndEdge) {
    const std::string names = "! I0.0=B1a\n! I0.1=B2a\n! I0.2=B1b\n! I0.3=B2b\n! I0.4=Closed\n"
                              "! I0.5=Locked\n! I0.6=Safe\n! I0.7=Start\n! M0.10=Unlock1\n"
                              "! M0.11=Unlock2\n! M0.0=OutA\n! M0.1=OutB\n! R0.0=DiagA\n"
                              "! R0.1=DiagB\n! R0.2=LockDiag1\n! R0.3=LockDiag2\n";
    const std::string code =
        ";@block SF_TwoHandControlTypeIII S_Button1=\"B1a\" S_Button2=\"B2a\" "
        "S_TwoHandOut=\"OutA\" DiagCode=\"DiagA\"\n;@end\n"
        ";@block SF_TwoHandControlTypeIII S_Button1=\"B1b\" S_Button2=\"B2b\" "
        "S_TwoHandOut=\"OutB\" DiagCode=\"DiagB\"\n;@end\n"
        ";@block SF_GuardLocking S_GuardMonitoring=\"Closed\" S_GuardLock=\"Locked\" "
        "S_SafetyActive=\"Safe\" S_StartReset=\"Start\" UnlockRequest=\"Unlock1\" "
        "DiagCode=\"LockDiag1\"\n;@end\n"
        ";@block SF_GuardLocking S_GuardMonitoring=\"Closed\" S_GuardLock=\"Locked\" "
        "S_SafetyActive=\"Safe\" S_StartReset=\"Start\" UnlockRequest=\"Unlock2\" "
        "DiagCode=\"LockDiag2\"\n;@end\n";
    EXPECT_TRUE(holdsOnBothInstructionSets(names, code, R"(
set Closed 1
set Locked 1
set Safe 1
set Start 1
scans 2
expect DiagA -32764
expect DiagB -32764
expect LockDiag1 -32768
expect LockDiag2 -32768
set B1a 1
scans 1
expect DiagA -32763
run 300ms
set B1b 1
scans 1
expect DiagB -32763
# the first instance's 500 ms run out, the second's do not
run 200ms
expect DiagA -16379
expect DiagB -32763
set B2b 1
scans 1
expect DiagB -32768
expect OutB 1
expect OutA 0
# each lock sees its own request
set Unlock1 1
scans 1
expect LockDiag1 -32749
expect LockDiag2 -32768
set Unlock2 1
scans 1
expect LockDiag2 -32749
expect LockDiag1 -32749
)"));
}

TEST(SafetyInstances, EdmAndMutingInstancesInOneUnitHaveTheirOwnTimersAndEdges) {
    const std::string names = "! I0.0=Ctl1\n! I0.1=Ctl2\n! I0.2=Fb1\n! I0.3=Fb2\n! I0.4=Start\n"
                              "! I0.5=Aopd\n! I0.6=Lamp\n! I0.7=Enable\n! I0.10=A11\n"
                              "! I0.11=A12\n! I0.12=B11\n! I0.13=B12\n! I0.17=Rear\n"
                              "! R0.0=EdmDiag1\n! R0.1=EdmDiag2\n! R0.2=MuteDiag1\n"
                              "! R0.3=MuteDiag2\n";
    const std::string code =
        ";@block SF_EDM S_OutControl=\"Ctl1\" S_EDM1=\"Fb1\" S_EDM2=\"Fb1\" "
        "MonitoringTime=\"0s05\" S_StartReset=\"Start\" DiagCode=\"EdmDiag1\"\n;@end\n"
        ";@block SF_EDM S_OutControl=\"Ctl2\" S_EDM1=\"Fb2\" S_EDM2=\"Fb2\" "
        "MonitoringTime=\"0s10\" S_StartReset=\"Start\" DiagCode=\"EdmDiag2\"\n;@end\n"
        ";@block SF_MutingSeq S_AOPD_In=\"Aopd\" MutingSwitch11=\"A11\" MutingSwitch12=\"A12\" "
        "MutingSwitch21=\"Rear\" MutingSwitch22=\"Rear\" S_MutingLamp=\"Lamp\" "
        "MaxMutingTime=\"1s00\" MutingEnable=\"Enable\" S_StartReset=\"Start\" "
        "DiagCode=\"MuteDiag1\"\n;@end\n"
        ";@block SF_MutingSeq S_AOPD_In=\"Aopd\" MutingSwitch11=\"B11\" MutingSwitch12=\"B12\" "
        "MutingSwitch21=\"Rear\" MutingSwitch22=\"Rear\" S_MutingLamp=\"Lamp\" "
        "MaxMutingTime=\"1s00\" MutingEnable=\"Enable\" S_StartReset=\"Start\" "
        "DiagCode=\"MuteDiag2\"\n;@end\n";
    EXPECT_TRUE(holdsOnBothInstructionSets(names, code, R"(
set Start 1
set Fb1 1
set Fb2 1
set Aopd 1
set Lamp 1
scans 3
expect EdmDiag1 -30704
expect EdmDiag2 -30704
expect MuteDiag1 -32768
expect MuteDiag2 -32768
# both switched on in scan s, neither feedback follows: C090 in s + 6 and s + 11
set Ctl1 1
set Ctl2 1
scans 7
expect EdmDiag1 -16240
expect EdmDiag2 -32768
scans 4
expect EdmDiag2 -32768
scans 1
expect EdmDiag2 -16240
# each muting sees its own sensors' edges
set Enable 1
set A11 1
scans 1
expect MuteDiag1 -32751
expect MuteDiag2 -32768
set B11 1
scans 1
expect MuteDiag2 -32751
set A12 1
scans 1
expect MuteDiag1 -32750
expect MuteDiag2 -32751
)"));
}
