// SPDX-License-Identifier: GPL-3.0-or-later
#include "SimulationFixture.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <string>

using rs::test::Simulated;

namespace {

// Two units with every instruction the machine code has in line (contacts,
// edges and outputs on bytes and register bits, nested parallel branches,
// loads, comparisons, register arithmetic with saturation) and the ones it
// calls (timers, toggles, divisions, double registers, jumps, sequence
// reset, system instructions).
const char* const kMachineCodeProgram = R"(! id_pluto:00=000000000000
;@var R0.2 export="yes"
! type_pluto:00=A20,is3
! id_pluto:01=000000000000
! type_pluto:01=A20,is3
! pgm_pluto:00
S0.0_0
Q0.1 = I0.0 * (I0.1 + /I0.2 * (I0.3 + I0.4) + P(I0.5)) * /I0.6
M0.1 = P(I0.3) * /I0.4 + N(/I0.7) * R0.100.3
M0.2 = /P(I0.3) + /N(R0.100.3) * I1.2
M0.3 = P(R0.101.9) + N(I0.1)
T(Q0.2) = P(I0.5)
S(M0.4) = I0.6 * M0.1
R(M0.4) = I0.7
M0.5 = SM0.1
S(R0.100.3) = I0.0
R(R0.100.3) = I0.1
R0.100.12 = I0.2 + M0.2
M0.6 = R0.100.12 * /R0.100.3
T(R0.101.9) = P(I0.4)
M0.7 = I0.0 * TON(0s05) + I0.1 * TPS(0s03) + I0.2 * TOF(0s04)
(R0.1++) = I0.6
(R0.2 += R0.1) = I0.3
(R0.6 -= R0.2) = I0.4
(R0.7 = R0.1 * R0.2) = I0.5
(R0.8 = R0.6 - R0.7) = I1.2
(R0.9 = R0.8 + R0.2) = /I0.0
(R0.10 = 1234) = P(I0.2)
(R0.11 *= R0.7) = I0.7
(R0.3 = R0.2 / R0.1) = P(I0.7)
(DR0.20 = DR0.20 * 3) = P(I0.2)
(R0.12 = DR0.20) = I0.1
M0.8 = (R0.1 > 4) * I0.5 + (R0.2 <= R0.1) + /(R0.6 = R0.7) * (R0.8 >= 0)
M0.9 = (R0.9 < R0.10) + (R0.1 = 7)
(R0.4 = SR0.2) = M0.8
GM0.1 = M0.8 * I0.6
;@system DRegisterValid Input="DR0.20" Valid="M0.24" Value="DR0.30"
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
(R0.5 += R0.1) = M0.22
J(0) = M0.22
! pgm_pluto:01
S1.0_0
Q1.1 = I0.0 * GM0.1 + /I1.2
;@system RegisterValid Input="R0.2" Valid="M1.2" Value="R1.5"
M1.1 = P(I0.3) * I1.1
S(Q1.2) = GM0.1
R(Q1.2) = I1.3
(R1.1 = R1.2 + R1.3) = I1.0
(R1.4 *= R1.1) = P(I0.2)
)";

// Runs `make` with the machine code on or off (the environment variable
// RUNGSMITH_NO_JIT, docs/simulator.md), and leaves the environment as it was.
template <typename Result> Result withMachineCode(bool on, const std::function<Result()>& make) {
    const char* before = std::getenv("RUNGSMITH_NO_JIT");
    const std::string saved = before ? before : "";
    if (on)
        unsetenv("RUNGSMITH_NO_JIT");
    else
        setenv("RUNGSMITH_NO_JIT", "1", 1);
    Result result = make();
    if (before)
        setenv("RUNGSMITH_NO_JIT", saved.c_str(), 1);
    else
        unsetenv("RUNGSMITH_NO_JIT");
    return result;
}

// Machine code and interpreter agree on every variable, step and
// conduction after every scan, over random inputs, register values and
// forces.
TEST(MachineCodeTest, DoesWhatTheInterpreterDoes) {
    auto compiled = withMachineCode<std::unique_ptr<Simulated>>(
        true, [] { return std::make_unique<Simulated>(kMachineCodeProgram); });
    auto interpreted = withMachineCode<std::unique_ptr<Simulated>>(
        false, [] { return std::make_unique<Simulated>(kMachineCodeProgram); });
    std::mt19937 random(20260101);
    const auto pick = [&random](int n) {
        return static_cast<std::size_t>(std::uniform_int_distribution<int>(0, n - 1)(random));
    };
    for (int scan = 0; scan < 3000; ++scan) {
        for (int unit = 0; unit < 2; ++unit) {
            auto& a = compiled->simulation->unit(unit)->memory();
            auto& b = interpreted->simulation->unit(unit)->memory();
            for (int i = 0; i < 3; ++i) {
                const std::size_t input = pick(12);
                a.inputs[input] = b.inputs[input] = !a.inputs[input];
            }
            if (pick(10) == 0) { // values near the limits, so that arithmetic saturates
                const std::size_t r = 1 + pick(12);
                const auto value = static_cast<std::int16_t>(
                    std::uniform_int_distribution<int>(-32768, 32767)(random));
                a.registers[r] = b.registers[r] = value;
            }
        }
        // Forces and releases make the engines translate their code again.
        const auto both = [&](const std::function<void(Simulated&)>& change) {
            withMachineCode<bool>(true, [&] { return change(*compiled), true; });
            withMachineCode<bool>(false, [&] { return change(*interpreted), true; });
        };
        for (const char* word : {"M0.4", "R0.2", "R0.100.3", "Q0.2", "M0.23", "R0.13"}) {
            if (scan % 500 == 250)
                both([&](Simulated& s) { s.set(word, static_cast<std::int64_t>(scan % 3)); });
            if (scan % 500 == 400)
                both([&](Simulated& s) { s.simulation->release(Simulated::at(word)); });
        }
        compiled->scans(1);
        interpreted->scans(1);
        for (int unit = 0; unit < 2; ++unit) {
            const auto* a = compiled->simulation->unit(unit);
            const auto* b = interpreted->simulation->unit(unit);
            ASSERT_EQ(std::memcmp(&a->memory(), &b->memory(), sizeof a->memory()), 0)
                << "unit " << unit << ", scan " << scan;
            ASSERT_EQ(a->activeStep(1), b->activeStep(1)) << "scan " << scan;
            ASSERT_EQ(a->conduction(), b->conduction()) << "unit " << unit << ", scan " << scan;
        }
    }
}

} // namespace
