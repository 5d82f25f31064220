// SPDX-License-Identifier: GPL-3.0-or-later
#include "RandomScanProgram.h"
#include "compiler/Compiler.h"
#include "prove/ScanModel.h"
#include "prove/Unrolling.h"
#include "sim/Simulation.h"

#include <gtest/gtest.h>

#include <random>

namespace {

using rs::prove::AndGraph;
using rs::prove::Lit;
using rs::prove::ScanModel;
using rs::prove::Word;

rs::lang::Address at(const std::string& word) {
    return rs::lang::readAddressWord(word).address;
}

std::string errors(const rs::compiler::CompileResult& compiled) {
    std::string text;
    for (const auto& d : compiled.diagnostics)
        if (d.severity == rs::lang::Severity::Error)
            text += std::to_string(d.line) + ": " + d.message + "\n";
    return text;
}

// Every variable a random program can touch, by address.
std::vector<rs::lang::Address> observed() {
    std::vector<rs::lang::Address> addresses;
    for (int unit = 0; unit < 2; ++unit) {
        const std::string u = std::to_string(unit);
        for (int i = 0; i <= 4; ++i)
            addresses.push_back(at("I" + u + "." + std::to_string(i)));
        for (int i = 0; i <= 3; ++i)
            addresses.push_back(at("Q" + u + "." + std::to_string(i)));
        for (int i = 0; i <= 5; ++i)
            addresses.push_back(at("M" + u + "." + std::to_string(i)));
        for (int i = 0; i <= 2; ++i)
            addresses.push_back(at("GM" + u + "." + std::to_string(i)));
        for (int i = 0; i <= 5; ++i)
            addresses.push_back(at("R" + u + "." + std::to_string(i)));
        for (int i = 0; i <= 12; ++i)
            addresses.push_back(at("SM" + u + "." + std::to_string(i)));
        addresses.push_back(at("SR" + u + ".2"));
        addresses.push_back(at("S" + u + ".1"));
    }
    return addresses;
}

// The program's scans, in the engine and in the circuit, from power on with
// the same random inputs: after every scan every variable, every active step
// and every timer agree.
void compareScans(const std::string& text, unsigned seed, int scans) {
    const rs::compiler::CompileResult compiled = rs::compiler::compileText(text);
    ASSERT_EQ(compiled.errors(), 0) << text << errors(compiled);
    ScanModel model(compiled.images, 10);
    ASSERT_TRUE(model.abstractions().empty()) << model.abstractions().front();
    const std::vector<rs::lang::Address> addresses = observed();
    std::vector<Word> after;
    for (const auto& address : addresses)
        after.push_back(model.valueAfterScan(address));
    rs::sim::Simulation simulation(compiled.images);
    const AndGraph& graph = model.graph();
    std::vector<std::uint64_t> values(graph.nodes(), 0);
    std::vector<bool> state;
    for (const auto& bit : model.state())
        state.push_back(bit.initial);
    std::mt19937 random(seed);
    for (int scan = 1; scan <= scans; ++scan) {
        for (const auto& input : model.inputs()) {
            std::int64_t value = simulation.value(input.address);
            if (input.bit) {
                if (random() % 4 == 0)
                    value = !value;
            } else if (random() % 3 == 0) {
                value = static_cast<std::int32_t>(random());
            }
            simulation.set(input.address, value);
            for (int i = 0; i < input.word.width(); ++i)
                values[rs::prove::nodeOf(input.word.bits[i])] =
                    ((value >> std::min(i, 63)) & 1) ? ~std::uint64_t{0} : 0;
        }
        for (std::size_t i = 0; i < state.size(); ++i)
            values[rs::prove::nodeOf(model.state()[i].current)] = state[i] ? ~std::uint64_t{0} : 0;
        graph.evaluate(values);
        simulation.scan();
        for (std::size_t i = 0; i < addresses.size(); ++i)
            ASSERT_EQ(rs::prove::laneValue(values, after[i], 0), simulation.value(addresses[i]))
                << rs::lang::toString(addresses[i]) << " after scan " << scan << " of\n"
                << text;
        for (const auto& image : compiled.images)
            for (int slot = 0; slot < image.timers; ++slot) {
                const auto timer = model.timerState(image.station, slot);
                ASSERT_TRUE(timer.has_value());
                const auto& engine = simulation.unit(image.station)->timer(slot);
                if (!(AndGraph::value(values, timer->ranLast) & 1))
                    continue; // a timer that did not run starts afresh: the rest is stale
                ASSERT_EQ(rs::prove::laneValue(values, timer->ticks, 0),
                          std::min(engine.elapsedMs / 10, timer->capTicks))
                    << "timer " << slot << " of unit " << image.station << " after scan " << scan
                    << " of\n"
                    << text;
                ASSERT_EQ(AndGraph::value(values, timer->running) & 1, engine.running);
                ASSERT_EQ(AndGraph::value(values, timer->lastInput) & 1, engine.lastInput);
            }
        for (std::size_t i = 0; i < state.size(); ++i)
            state[i] = AndGraph::value(values, model.state()[i].next) & 1;
    }
}

// Random programs: timers, edges, sequences, saturation, division and two
// units on one bus.
TEST(ScanModelDifferentialTest, EveryScanIsTheEnginesScan) {
    for (unsigned seed = 1; seed <= 300; ++seed) {
        compareScans(rs::test::RandomScanProgram(seed).text(), seed, 60);
        if (HasFatalFailure())
            return;
    }
}

// What random programs rarely do: a step left and entered again, with its
// edges and timers where they were; the timer freeze; a sequence held in
// step 0 from the PLC code.
TEST(ScanModelDifferentialTest, StepsLeftAndEnteredAgain) {
    const std::string unit = "! id_pluto:00=000000000000\n! type_pluto:00=A20,is3\n"
                             "! pgm_pluto:00\nS0.0_0\n";
    const std::string programs[] = {
        unit + "R(S0.1) = I0.3\nS0.1_0\nJ(1) = I0.0\nS0.1_1\nQ0.0 = P(I0.1)\n"
               "M0.1 = N(/I0.2)\nJ(0) = I0.4\n",
        unit + "S0.1_0\nJ(1) = I0.0\nS0.1_1\nQ0.1 = I0.1 * TON(0s03)\nQ0.2 = I0.2 * TOF(0s02)\n"
               "Q0.3 = I0.1 * TPS(0s04)\nJ(0) = /I0.0\n",
        unit + "SM0.10 = I0.0\nQ0.0 = I0.1 * TON(0s03)\nQ0.1 = I0.1 * TOF(0s02)\n",
        unit + "(R0.1 = R0.2 / R0.3) = I0.0\n(R0.4 *= R0.1) = I0.1\n(R0.2 -= 7) = I0.2\n"
               "(R0.3++) = P(I0.3)\nQ0.0 = (R0.4 > 100) * SM0.12\n",
    };
    unsigned seed = 7;
    for (const std::string& text : programs)
        for (int run = 0; run < 20; ++run) {
            compareScans(text, ++seed, 200);
            if (HasFatalFailure())
                return;
        }
}

// The solver's encoding of a scan is the circuit's: from states the engine
// reached, with the scan's inputs fixed, the only successor the solver
// allows is the one the circuit computes.
TEST(ScanModelDifferentialTest, TheSolverFindsTheSameSuccessor) {
    for (unsigned seed = 1000; seed < 1040; ++seed) {
        const std::string text = rs::test::RandomScanProgram(seed).text();
        const rs::compiler::CompileResult compiled = rs::compiler::compileText(text);
        ASSERT_EQ(compiled.errors(), 0) << text << errors(compiled);
        ScanModel model(compiled.images, 10);
        const AndGraph& graph = model.graph();
        std::vector<std::uint64_t> values(graph.nodes(), 0);
        std::vector<bool> state;
        for (const auto& bit : model.state())
            state.push_back(bit.initial);
        std::mt19937 random(seed);
        for (int scan = 0; scan < 30; ++scan) {
            std::vector<bool> inputs;
            for (const auto& input : model.inputs())
                for (int i = 0; i < input.word.width(); ++i) {
                    const bool bit = i + 1 < input.word.width() || !input.bit ? random() % 2 : 0;
                    inputs.push_back(bit);
                    values[rs::prove::nodeOf(input.word.bits[i])] = bit ? ~std::uint64_t{0} : 0;
                }
            for (std::size_t i = 0; i < state.size(); ++i)
                values[rs::prove::nodeOf(model.state()[i].current)] =
                    state[i] ? ~std::uint64_t{0} : 0;
            graph.evaluate(values);
            if (scan % 5 == 4) {
                rs::prove::Unrolling unrolling(model, true);
                std::vector<int> assumptions;
                for (std::size_t i = 0; i < state.size(); ++i) {
                    const int l = unrolling.literal(model.state()[i].current, 0);
                    assumptions.push_back(state[i] ? l : -l);
                }
                std::size_t k = 0;
                for (const auto& input : model.inputs())
                    for (Lit bit : input.word.bits) {
                        const int l = unrolling.literal(bit, 0);
                        assumptions.push_back(inputs[k++] ? l : -l);
                    }
                std::vector<int> next;
                for (const auto& bit : model.state())
                    next.push_back(unrolling.literal(bit.current, 1));
                ASSERT_EQ(unrolling.solve(assumptions), 10);
                for (std::size_t i = 0; i < state.size(); ++i)
                    ASSERT_EQ(unrolling.value(model.state()[i].current, 1),
                              bool(AndGraph::value(values, model.state()[i].next) & 1))
                        << "state bit " << i << " after scan " << scan;
            }
            for (std::size_t i = 0; i < state.size(); ++i)
                state[i] = AndGraph::value(values, model.state()[i].next) & 1;
        }
    }
}

} // namespace
