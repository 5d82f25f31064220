// SPDX-License-Identifier: GPL-3.0-or-later
#include "MarkingInterpreter.h"

#include "InstructionMeaning.h"
#include "SystemCalls.h"

#include <iterator>

namespace rs::sim::engine {

using compiler::Op;

namespace {

// A timer's ElementState after it ran with `input`: its output (before a
// negation), and whether it is counting.
std::uint8_t timerState(const Timer& timer, int kind, bool input) {
    const bool counting = kind == 0   ? input && !timer.output
                          : kind == 1 ? timer.running
                                      : timer.running && !input;
    return static_cast<std::uint8_t>((timer.output ? Closed : 0) | (counting ? Running : 0));
}

} // namespace

// Threaded dispatch (GCC's labels as values): each handler jumps straight to
// the next one, so the processor predicts each transition on its own.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
void runMarking(UnitState& unit, int index, int& pendingJump, int cycleMs, Conduction* marks,
                std::uint8_t* states) {
    const StepRun& step = unit.steps[static_cast<std::size_t>(index)];
    if (step.count == 0)
        return;
    auto& sm = unit.memory.systemMemories;
    struct Branch {
        unsigned in;
        unsigned any;
    };
    Branch branches[64];
    int depth = 0;
    unsigned power = 1; // 0 or 1, combined with & and | so that nothing branches on it
    std::int64_t a = 0;
    std::int64_t b = 0;
    const DecodedInstruction* in = unit.code.data() + step.first;
    const DecodedInstruction* const end = in + step.count;
    Conduction* mark = marks + step.first;
    std::uint8_t* state = states + step.first; // only elements with a state of their own write it
    static_assert(compiler::Negated == 1);

    static const void* const handlers[] = {
        &&rung,       &&contactByte, &&contact,     &&edge,     &&timer,        &&loadA,
        &&loadB,      &&equal,       &&greater,     &&less,     &&greaterEqual, &&lessEqual,
        &&branchOpen, &&branchNext,  &&branchClose, &&coilByte, &&coil,         &&setByte,
        &&set,        &&resetByte,   &&reset,       &&toggle,   &&jump,         &&sequenceReset,
        &&arith,      &&system,      &&argument};
    static_assert(std::size(handlers) == HandlerCount);
#define RS_NEXT()                                                                                  \
    do {                                                                                           \
        *mark++ = static_cast<Conduction>(1 + power);                                              \
        ++state;                                                                                   \
        if (++in == end)                                                                           \
            return;                                                                                \
        goto* handlers[in->handler];                                                               \
    } while (false)
#define RS_NEGATED (in->flags & compiler::Negated)
#define RS_BYTE (*static_cast<std::uint8_t*>(in->ref))
#define RS_COMPARE(op)                                                                             \
    do {                                                                                           \
        const unsigned holds = static_cast<unsigned>(compares(op, a, b));                          \
        *state = static_cast<std::uint8_t>(holds);                                                 \
        power &= holds ^ RS_NEGATED;                                                               \
    } while (false)

    goto* handlers[in->handler];
rung:
    power = 1;
    RS_NEXT();
contactByte : {
    const unsigned closed = static_cast<unsigned>(RS_BYTE != 0) ^ RS_NEGATED;
    *state = static_cast<std::uint8_t>(closed);
    power &= closed;
    RS_NEXT();
}
contact : {
    const unsigned closed = static_cast<unsigned>(in->readBit()) ^ RS_NEGATED;
    *state = static_cast<std::uint8_t>(closed);
    power &= closed;
    RS_NEXT();
}
edge : {
    const unsigned closed = unit.edge(*in);
    *state = static_cast<std::uint8_t>(closed);
    power &= closed;
    RS_NEXT();
}
timer : {
    const bool input = power != 0;
    power = unit.timer(*in, input, cycleMs);
    *state = timerState(unit.timers[in->slot], in->aux, input);
    RS_NEXT();
}
loadA:
    a = (in->flags & compiler::ConstantOperand) ? in->constant : in->readWord();
    RS_NEXT();
loadB:
    b = (in->flags & compiler::ConstantOperand) ? in->constant : in->readWord();
    RS_NEXT();
equal:
    RS_COMPARE(lang::CompareOp::Equal);
    RS_NEXT();
greater:
    RS_COMPARE(lang::CompareOp::Greater);
    RS_NEXT();
less:
    RS_COMPARE(lang::CompareOp::Less);
    RS_NEXT();
greaterEqual:
    RS_COMPARE(lang::CompareOp::GreaterEqual);
    RS_NEXT();
lessEqual:
    RS_COMPARE(lang::CompareOp::LessEqual);
    RS_NEXT();
branchOpen:
    branches[depth++] = {power, 0};
    RS_NEXT();
branchNext:
    branches[depth - 1].any |= power;
    power = branches[depth - 1].in;
    RS_NEXT();
branchClose:
    power |= branches[--depth].any;
    RS_NEXT();
coilByte:
    RS_BYTE = static_cast<std::uint8_t>(outputBit<Op::Coil>(power, RS_BYTE));
    sm[kDitto] = static_cast<std::uint8_t>(power);
    RS_NEXT();
coil:
    in->writeBit(outputBit<Op::Coil>(power, in->readBit()));
    sm[kDitto] = static_cast<std::uint8_t>(power);
    RS_NEXT();
setByte:
    RS_BYTE = static_cast<std::uint8_t>(outputBit<Op::Set>(power, RS_BYTE));
    sm[kDitto] = static_cast<std::uint8_t>(power);
    RS_NEXT();
set:
    if (power)
        in->writeBit(outputBit<Op::Set>(1, in->readBit()));
    sm[kDitto] = static_cast<std::uint8_t>(power);
    RS_NEXT();
resetByte:
    RS_BYTE = static_cast<std::uint8_t>(outputBit<Op::Reset>(power, RS_BYTE));
    sm[kDitto] = static_cast<std::uint8_t>(power);
    RS_NEXT();
reset:
    if (power)
        in->writeBit(outputBit<Op::Reset>(1, in->readBit()));
    sm[kDitto] = static_cast<std::uint8_t>(power);
    RS_NEXT();
toggle:
    if (power)
        in->writeBit(outputBit<Op::Toggle>(1, in->readBit()));
    sm[kDitto] = static_cast<std::uint8_t>(power);
    RS_NEXT();
jump:
    *state = static_cast<std::uint8_t>(power);
    if (power)
        pendingJump = in->slot; // the last jump taken in the step wins
    RS_NEXT();
sequenceReset:
    *state = static_cast<std::uint8_t>(power);
    if (power && in->slot < 10)
        unit.sequences[in->slot].resetRequested = true;
    RS_NEXT();
arith:
    *state = static_cast<std::uint8_t>(power);
    if (power)
        unit.arithmetic(*in, a, b);
    RS_NEXT();
system:
    runSystemCall(unit, *in);
    power = 1;
    RS_NEXT();
argument:
    RS_NEXT();
#undef RS_COMPARE
#undef RS_BYTE
#undef RS_NEGATED
#undef RS_NEXT
}
#pragma GCC diagnostic pop

} // namespace rs::sim::engine
