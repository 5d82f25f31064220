// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "DecodedInstruction.h"
#include "InstructionMeaning.h"
#include "sim/GatewayTelegram.h"
#include "sim/Timer.h"
#include "sim/UnitMemory.h"

#include <array>
#include <cstdint>
#include <vector>

namespace rs::sim::engine {

constexpr int kMaxStep = 255;

// A step of a sequence: its instructions in the decoded code.
struct StepRun {
    int sequence;
    int step;
    std::uint32_t first;
    std::uint32_t count;
};

struct SequenceState {
    int active = 0;
    bool stepNew = true;
    bool resetRequested = false;
};

struct Sequence : SequenceState {
    std::vector<int> stepIndex; // step number -> index in UnitState::steps, -1 when absent
};

struct EdgeState {
    bool seen = false;
    bool last = false;
};

// What every tier of the engine runs on: the decoded code, the unit's memory
// and the state of its edges, timers and sequences. The instructions that the
// tiers run the same way (edges on any operand, timers, arithmetic in full)
// are here, inline, so that each tier's loop keeps them in line.
struct UnitState {
    UnitMemory memory;
    std::vector<DecodedInstruction> code;
    std::vector<StepRun> steps;
    std::array<Sequence, 10> sequences;
    std::vector<EdgeState> edges;
    std::vector<Timer> timers;
    std::uint64_t scan = 0; // scans since power on
    // What the ToGateway blocks sent in the scan that ran last.
    std::vector<GatewayTelegram> telegrams;

    // The power an edge occurrence passes: whether it sees its edge, negated if asked.
    unsigned edge(const DecodedInstruction& in) {
        EdgeState& state = edges[in.slot];
        const bool value = in.readBit() != bool(in.flags & compiler::OperandNegated);
        const unsigned seen = edgeSeen(state.seen, state.last, value, in.flags & compiler::Rising);
        state.seen = true;
        state.last = value;
        return seen ^ (in.flags & compiler::Negated);
    }

    bool timer(const DecodedInstruction& in, bool input, int cycleMs) {
        auto& freeze = memory.systemMemories[kTimerFreeze];
        const std::int64_t dt = freeze ? 0 : cycleMs;
        freeze = 0; // SM_TimerFreeze holds the next timer in the code only
        const std::int64_t preset =
            10 * ((in.flags & compiler::ConstantOperand) ? in.constant : in.readWord());
        return timers[in.slot].run(input, in.aux, preset, in.flags & compiler::Negated, dt, scan);
    }

    // An arithmetic output that has power, on any operand.
    void arithmetic(const DecodedInstruction& in, std::int64_t a, std::int64_t b) {
        auto& sm = memory.systemMemories;
        const Bounds bounds = in.wideWord() ? kDoubleRegisterBounds : kRegisterBounds;
        const std::int64_t current = in.readWord();
        const ArithmeticForm& form = kArithmeticForms[in.aux];
        std::int64_t result = 0;
        if (form.operation == ArithmeticForm::Operation::Divide) {
            const std::int64_t dividend = form.x(current, a);
            const std::int64_t divisor = form.y(a, b);
            sm[kDivByZero] = divisor == 0;
            if (divisor != 0) { // division by zero gives 0
                result = dividend / divisor;
                memory.systemRegisters[kRemain] = static_cast<std::int32_t>(dividend % divisor);
            }
        } else {
            result = form.undivided(current, a, b);
        }
        sm[kOverflow] = outside(result, bounds);
        if (!in.dropWrite) // a forced register keeps its value
            in.writeWord(saturated(result, bounds));
    }

    // The coils of a step that is left go off, and so do the bit outputs of
    // its system instructions, which are written every scan as coils are;
    // latched outputs and numbers keep their value.
    void leaveStep(int index) {
        const StepRun& step = steps[static_cast<std::size_t>(index)];
        for (std::uint32_t i = step.first; i < step.first + step.count; ++i)
            if (code[i].op == compiler::Op::Coil ||
                (code[i].op == compiler::Op::Argument && code[i].aux == compiler::ArgumentWritten &&
                 !(code[i].flags & compiler::ConstantOperand)))
                code[i].writeBit(false);
    }
};

} // namespace rs::sim::engine
