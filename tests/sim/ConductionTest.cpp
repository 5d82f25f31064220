// SPDX-License-Identifier: GPL-3.0-or-later
#include "SimulationFixture.h"

#include <gtest/gtest.h>

#include <cstring>

using rs::test::Simulated;

namespace {

// Two units with every kind of instruction: contacts on bytes and register
// bits, edges, timers, latches, toggles, comparisons, arithmetic, parallel
// branches, jumps, a sequence reset, SM_Ditto, system instructions and the
// other unit's variables.
const char* const kConductionProgram = R"(! id_pluto:00=000000000000
;@var R0.2 export="yes"
! type_pluto:00=A20,is3
! id_pluto:01=000000000000
! type_pluto:01=A20,is3
! pgm_pluto:00
S0.0_0
Q0.1 = I0.0 * (I0.1 + /I0.2)
M0.1 = P(I0.3) * /I0.4
M0.2 = N(I0.3) + P(/I0.5) * I1.2
T(Q0.2) = P(I0.5)
S(M0.3) = I0.6 * M0.1
R(M0.3) = I0.7
M0.4 = SM0.1
S(R0.100.3) = I0.0
R(R0.100.3) = I0.1
M0.5 = R0.100.3 * /I0.2
T(R0.101.9) = P(I0.4)
M0.6 = I0.0 * TON(0s05)
M0.7 = I0.1 * TPS(0s03) + I0.2 * TOF(0s04)
(R0.1++) = P(I0.6)
(R0.2 += R0.1) = I0.3
(R0.3 = R0.2 / R0.1) = P(I0.7)
(DR0.10 = DR0.10 * 3) = P(I0.2)
M0.8 = (R0.1 > 4) * I0.5 + (R0.2 <= R0.1)
(R0.4 = SR0.2) = M0.8
GM0.1 = M0.8 * I0.6
;@system DRegisterValid Input="DR0.10" Valid="M0.24" Value="DR0.30"
R(S0.1) = I0.1 * I0.2
S0.1_0
M0.20 = SM0.0
J(1) = P(I0.0)
S0.1_1
M0.21 = I0.4
;@system RegisterValid Input="R0.1" Valid="M0.23" Value="R0.13"
(R0.5--) = P(I0.5)
J(2) = I0.3 * I0.6
J(0) = P(I0.7)
S0.1_2
M0.22 = TON(0s10)
J(0) = M0.22
! pgm_pluto:01
S1.0_0
Q1.1 = I0.0 * GM0.1 + /I1.2
;@system RegisterValid Input="R0.2" Valid="M1.2" Value="R1.5"
M1.1 = P(I0.3) * I1.1
S(Q1.2) = GM0.1
R(Q1.2) = I1.3
)";

// A changing pattern of inputs, the same for every simulation.
void drive(Simulated& s, int scan) {
    for (int unit = 0; unit < 2; ++unit) {
        auto& inputs = s.simulation->unit(unit)->memory().inputs;
        inputs[static_cast<std::size_t>((scan * 5 + unit) % 8)] ^= 1;
        if (scan % 7 == 0)
            inputs[static_cast<std::size_t>((scan / 7) % 8)] ^= 1;
    }
}

void expectSameUnits(const Simulated& eager, const Simulated& onDemand, int scan) {
    for (int unit = 0; unit < 2; ++unit) {
        const auto* a = eager.simulation->unit(unit);
        const auto* b = onDemand.simulation->unit(unit);
        ASSERT_EQ(std::memcmp(&a->memory(), &b->memory(), sizeof a->memory()), 0)
            << "unit " << unit << ", scan " << scan;
        ASSERT_EQ(a->activeStep(1), b->activeStep(1)) << "scan " << scan;
        ASSERT_EQ(a->conduction(), b->conduction()) << "unit " << unit << ", scan " << scan;
        ASSERT_EQ(a->elementStates(), b->elementStates()) << "unit " << unit << ", scan " << scan;
    }
}

} // namespace

// A scan runs without marking conduction; conduction() replays it. What the
// replay reports must be exactly what marking during the scan gives.
TEST(Conduction, OnDemandIsWhatMarkingWhileScanningGives) {
    Simulated eager(kConductionProgram);
    Simulated onDemand(kConductionProgram);
    for (int unit = 0; unit < 2; ++unit)
        eager.simulation->unit(unit)->setEagerConduction(true);
    for (int scan = 0; scan < 600; ++scan) {
        drive(eager, scan);
        drive(onDemand, scan);
        eager.simulation->scan();
        onDemand.simulation->scan();
        expectSameUnits(eager, onDemand, scan);
    }
}

TEST(Conduction, IsThatOfTheLastScanWhenReadOnlyNowAndThen) {
    Simulated eager(kConductionProgram);
    Simulated onDemand(kConductionProgram);
    for (int unit = 0; unit < 2; ++unit)
        eager.simulation->unit(unit)->setEagerConduction(true);
    for (int scan = 0; scan < 300; ++scan) {
        drive(eager, scan);
        drive(onDemand, scan);
        eager.simulation->scan();
        onDemand.simulation->scan();
        if (scan % 13 == 0)
            expectSameUnits(eager, onDemand, scan);
    }
}

TEST(Conduction, DoesNotChangeWhenInputsAreSetAfterTheScan) {
    Simulated eager(kConductionProgram);
    Simulated onDemand(kConductionProgram);
    eager.simulation->unit(0)->setEagerConduction(true);
    for (int scan = 0; scan < 40; ++scan) {
        drive(eager, scan);
        drive(onDemand, scan);
        eager.simulation->scan();
        onDemand.simulation->scan();
    }
    // What the GUI does between scans: set inputs, force a variable.
    for (Simulated* s : {&eager, &onDemand}) {
        s->set("I0.0", 1);
        s->set("I0.3", 1);
        s->set("M0.1", 1);
    }
    EXPECT_EQ(eager.simulation->unit(0)->conduction(), onDemand.simulation->unit(0)->conduction());
    eager.simulation->scan();
    onDemand.simulation->scan();
    expectSameUnits(eager, onDemand, 40);
}
