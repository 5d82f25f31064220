// SPDX-License-Identifier: GPL-3.0-or-later
#include "FastInterpreter.h"

#include "InstructionMeaning.h"
#include "SystemCalls.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <iterator>
#include <utility>

namespace rs::sim::engine {

namespace {

using compiler::ArithOp;
using compiler::Op;

// UnitState::edge() for a byte operand, without branches on the data.
unsigned byteEdge(const ByteEdge& e) {
    const unsigned value = static_cast<unsigned>(*e.operand != 0) ^ e.operandNegated;
    const unsigned last = e.state->last;
    const unsigned seen = edgeSeen(e.state->seen, last, value, e.rising != 0);
    e.state->seen = true;
    e.state->last = value != 0;
    return seen ^ e.negated;
}

} // namespace

template <int kind> unsigned fastOp(FastContext& context, const void* arg, unsigned power);

void FastInterpreter::translate(UnitState& unit) {
    const void* const* const table = handlerAddresses();
    m_ops.clear();
    m_stepStart.clear();
    m_byteEdges.clear();
    // m_ops points into m_byteEdges: it must not grow once filled.
    m_byteEdges.reserve(static_cast<std::size_t>(
        std::count_if(unit.code.begin(), unit.code.end(),
                      [](const DecodedInstruction& d) { return d.handler == HEdge; })));
    const std::size_t rungs = static_cast<std::size_t>(
        std::count_if(unit.code.begin(), unit.code.end(),
                      [](const DecodedInstruction& d) { return d.handler == HRung; }));
    m_bitStatements.clear();
    m_bitStatements.reserve(rungs);
    m_bitStatementRows.clear();
    m_bitStatementRows.reserve(rungs);
    m_wordStatements.clear();
    m_wordStatements.reserve(rungs);
    m_wordStatementRows.clear();
    m_wordStatementRows.reserve(rungs);
    std::vector<FastHandler> kinds; // of m_ops's entries
    for (const StepRun& step : unit.steps) {
        m_stepStart.push_back(static_cast<std::uint32_t>(m_ops.size()));
        const std::size_t begin = m_ops.size();
        const auto last = [&] {
            return m_ops.size() > begin ? kinds.back() : FEnd;
        };
        const auto replaceLast = [&](FastHandler kind) {
            kinds.back() = kind;
            m_ops.back().handler = table[kind];
        };
        for (std::uint32_t i = step.first; i < step.first + step.count; ++i) {
            DecodedInstruction& d = unit.code[i];
            const bool negated = d.flags & compiler::Negated;
            void* arg = &d;
            FastHandler kind = FEnd;
            if (d.handler == HRung) {
                std::uint32_t end = i + 1;
                while (end < step.first + step.count && unit.code[end].handler != HRung &&
                       unit.code[end].handler != HSystem)
                    ++end;
                BitStatement statement{};
                if (toBitStatement(unit, i, end, statement)) {
                    m_bitStatements.push_back(statement);
                    if (last() == FBitStatements) {
                        m_bitStatementRows.back().end = &m_bitStatements.back() + 1;
                    } else {
                        m_bitStatementRows.push_back(
                            {&m_bitStatements.back(), &m_bitStatements.back() + 1});
                        m_ops.push_back({table[FBitStatements], &m_bitStatementRows.back()});
                        kinds.push_back(FBitStatements);
                    }
                    i = end - 1;
                    continue;
                }
                WordStatement word{};
                if (toWordStatement(unit, i, end, word)) {
                    m_wordStatements.push_back(word);
                    if (last() == FWordStatements) {
                        m_wordStatementRows.back().end = &m_wordStatements.back() + 1;
                    } else {
                        m_wordStatementRows.push_back(
                            {&m_wordStatements.back(), &m_wordStatements.back() + 1});
                        m_ops.push_back({table[FWordStatements], &m_wordStatementRows.back()});
                        kinds.push_back(FWordStatements);
                    }
                    i = end - 1;
                    continue;
                }
            }
            switch (static_cast<Handler>(d.handler)) {
            case HRung:
                // Power is 1 after a byte output when the next statement starts.
                if (last() == FCoilByte || last() == FSetByte || last() == FResetByte) {
                    replaceLast(static_cast<FastHandler>(last() + 1));
                    continue;
                }
                kind = FRung;
                break;
            case HContactByte:
                arg = d.ref;
                kind = negated ? FAndNot : FAnd;
                if (last() == FRung) {
                    m_ops.pop_back();
                    kinds.pop_back();
                    kind = negated ? FStartNot : FStart;
                }
                break;
            case HContact:
                kind = d.refKind == static_cast<std::uint8_t>(BitRef::Kind::RegisterBit)
                           ? FContactRegisterBit
                           : FContact;
                break;
            case HEdge: {
                const bool byte = d.refKind == static_cast<std::uint8_t>(BitRef::Kind::Byte);
                if (byte) {
                    m_byteEdges.push_back(
                        {static_cast<const std::uint8_t*>(d.ref), &unit.edges[d.slot],
                         static_cast<std::uint8_t>((d.flags & compiler::OperandNegated) != 0),
                         static_cast<std::uint8_t>((d.flags & compiler::Rising) != 0),
                         static_cast<std::uint8_t>(negated)});
                    arg = &m_byteEdges.back();
                }
                kind = byte ? FByteEdge : FEdge;
                if (last() == FRung) {
                    m_ops.pop_back();
                    kinds.pop_back();
                    kind = byte ? FByteEdgeStart : FEdgeStart;
                }
                break;
            }
            case HTimer:
                kind = FTimer;
                break;
            case HLoadA:
            case HLoadB: {
                const bool isA = d.handler == HLoadA;
                if (d.flags & compiler::ConstantOperand) {
                    arg = &d.constant;
                    kind = isA ? FLoadAConstant : FLoadBConstant;
                } else if (d.refKind == static_cast<std::uint8_t>(WordRef::Kind::Register)) {
                    arg = d.ref;
                    kind = isA ? FLoadAWord : FLoadBWord;
                } else {
                    kind = isA ? FLoadA : FLoadB;
                }
                break;
            }
            case HEqual:
            case HGreater:
            case HLess:
            case HGreaterEqual:
            case HLessEqual:
                kind = static_cast<FastHandler>(FEqual + (d.handler - HEqual));
                break;
            case HBranchOpen:
                kind = FBranchOpen;
                break;
            case HBranchNext:
                kind = FBranchNext;
                break;
            case HBranchClose:
                kind = FBranchClose;
                break;
            case HCoilByte:
                arg = d.ref;
                kind = FCoilByte;
                break;
            case HCoil:
                kind = d.refKind == static_cast<std::uint8_t>(BitRef::Kind::RegisterBit)
                           ? FCoilRegisterBit
                           : FCoil;
                break;
            case HSetByte:
                arg = d.ref;
                kind = FSetByte;
                break;
            case HSet:
                kind = FSet;
                break;
            case HResetByte:
                arg = d.ref;
                kind = FResetByte;
                break;
            case HReset:
                kind = FReset;
                break;
            case HToggle:
                kind = FToggle;
                break;
            case HJump:
                kind = FJump;
                break;
            case HSequenceReset:
                kind = FSequenceReset;
                break;
            case HArith: {
                const auto op = static_cast<ArithOp>(d.aux);
                const bool plain =
                    d.refKind == static_cast<std::uint8_t>(WordRef::Kind::Register) &&
                    !d.dropWrite && !isDivision(op);
                kind = plain ? FArithRegister : FArith;
                break;
            }
            case HSystem:
                kind = FSystem;
                break;
            case HArgument:
                continue; // FSystem reads it
            case HandlerCount:
                break;
            }
            m_ops.push_back({table[kind], arg});
            kinds.push_back(kind);
        }
        m_ops.push_back({table[FEnd], nullptr});
        kinds.push_back(FEnd);
    }
    for (std::size_t i = 0; i < m_ops.size(); ++i) {
        if (kinds[i] != FBitStatements)
            continue;
        const auto& row = *static_cast<const Row<BitStatement>*>(m_ops[i].arg);
        if (std::all_of(row.first, row.end,
                        [this](const BitStatement& st) { return st.edge == &m_noEdge; }))
            m_ops[i].handler = table[FBitStatementsWithoutEdges];
    }
}

bool FastInterpreter::toBitStatement(UnitState& unit, std::uint32_t first, std::uint32_t end,
                                     BitStatement& out) {
    static const std::uint8_t one = 1;
    static const std::uint8_t zero = 0;
    static std::uint8_t nowhere = 0; // the target of a jump
    if (end - first < 2)
        return false;
    // The byte and mask of a bit operand (a register's bits are bytes in
    // memory order, so this needs a little-endian machine).
    const auto locate = [](const DecodedInstruction& d, const std::uint8_t*& byte,
                           std::uint8_t& mask) {
        if (d.refKind == static_cast<std::uint8_t>(BitRef::Kind::Byte)) {
            byte = static_cast<const std::uint8_t*>(d.ref);
            mask = 0xFF;
            return true;
        }
        if (d.refKind != static_cast<std::uint8_t>(BitRef::Kind::RegisterBit) ||
            std::endian::native != std::endian::little)
            return false;
        byte = static_cast<const std::uint8_t*>(d.ref) + d.bit / 8;
        mask = static_cast<std::uint8_t>(1u << (d.bit % 8));
        return true;
    };
    for (int i = 0; i < 2; ++i) {
        out.read[i] = &one;
        out.mask[i] = 0xFF;
    }
    out.read[2] = &zero;
    out.mask[2] = 0xFF;
    out.edge = &m_noEdge;
    out.edgeNegated = 1;
    int contacts = 0;
    bool edge = false;
    for (std::uint32_t i = first + 1; i + 1 < end; ++i) {
        const DecodedInstruction& d = unit.code[i];
        const auto negated = static_cast<std::uint8_t>(d.flags & compiler::Negated);
        if (d.op == Op::Contact && contacts < 2) {
            if (!locate(d, out.read[contacts], out.mask[contacts]))
                return false;
            out.negated[contacts++] = negated;
        } else if (d.op == Op::Edge && !edge) {
            if (!locate(d, out.read[2], out.mask[2]))
                return false;
            edge = true;
            out.edge = &unit.edges[d.slot];
            out.negated[2] = (d.flags & compiler::OperandNegated) != 0;
            out.edgeRising = (d.flags & compiler::Rising) != 0;
            out.edgeNegated = negated;
        } else {
            return false;
        }
    }
    const DecodedInstruction& output = unit.code[end - 1];
    if (output.op == Op::Jump) {
        out.keepOff = 0xFF;
        if (output.slot > kMaxStep)
            return false;
        out.target = &nowhere;
        out.jump = 1;
        out.jumpStep = static_cast<std::uint8_t>(output.slot);
        return true;
    }
    const std::uint8_t* target = nullptr;
    if (!locate(output, target, out.targetMask))
        return false;
    out.target = const_cast<std::uint8_t*>(target);
    // A byte output is 0 or 1, a register bit its own bit.
    out.targetOne = out.targetMask == 0xFF ? 1 : out.targetMask;
    switch (output.op) {
    case Op::Coil:
    case Op::Set:
    case Op::Reset:
    case Op::Toggle: {
        const OutputForm form = outputForm(output.op);
        out.keepOn = form.keepOn;
        out.flipOn = form.flipOn;
        out.keepOff = form.keepOff ? 0xFF : static_cast<std::uint8_t>(~out.targetMask);
        return true;
    }
    default:
        return false;
    }
}

bool FastInterpreter::toWordStatement(UnitState& unit, std::uint32_t first, std::uint32_t end,
                                      WordStatement& out) {
    static const std::uint8_t one = 1;
    static const std::uint8_t zero = 0;
    static const std::int32_t nothing = 0;
    if (end - first < 2 || std::endian::native != std::endian::little)
        return false;
    const DecodedInstruction& output = unit.code[end - 1];
    const auto op = static_cast<ArithOp>(output.aux);
    if (output.op != Op::Arith || output.dropWrite || isDivision(op) ||
        output.refKind != static_cast<std::uint8_t>(WordRef::Kind::Register))
        return false;
    out.target = static_cast<std::int16_t*>(output.ref);
    out.read[0] = &one;
    out.mask[0] = 0xFF;
    out.read[1] = &zero;
    out.mask[1] = 0xFF;
    out.edge = &m_noEdge;
    out.edgeNegated = 1;
    out.load[0] = out.load[1] = reinterpret_cast<const std::uint8_t*>(&nothing);
    bool contact = false;
    bool edge = false;
    int loads = 0; // a, then b
    for (std::uint32_t i = first + 1; i + 1 < end; ++i) {
        const DecodedInstruction& d = unit.code[i];
        const bool byte = d.refKind == static_cast<std::uint8_t>(BitRef::Kind::Byte);
        const bool series = loads == 0;
        if (d.op == Op::Contact && !contact && byte && series) {
            contact = true;
            out.read[0] = static_cast<const std::uint8_t*>(d.ref);
            out.negated[0] = d.flags & compiler::Negated;
        } else if (d.op == Op::Edge && !edge && byte && series) {
            edge = true;
            out.read[1] = static_cast<const std::uint8_t*>(d.ref);
            out.edge = &unit.edges[d.slot];
            out.negated[1] = (d.flags & compiler::OperandNegated) != 0;
            out.edgeRising = (d.flags & compiler::Rising) != 0;
            out.edgeNegated = d.flags & compiler::Negated;
        } else if ((d.op == Op::LoadA && loads == 0) || (d.op == Op::LoadB && loads < 2)) {
            const int which = d.op == Op::LoadA ? 0 : 1;
            loads = which + 1;
            out.loads[which] = 1;
            if (d.flags & compiler::ConstantOperand) {
                out.load[which] = reinterpret_cast<const std::uint8_t*>(&d.constant);
            } else if (d.refKind == static_cast<std::uint8_t>(WordRef::Kind::Register)) {
                out.load[which] = static_cast<const std::uint8_t*>(d.ref);
                out.narrow[which] = 16;
            } else if (d.refKind != static_cast<std::uint8_t>(WordRef::Kind::None)) {
                out.load[which] = static_cast<const std::uint8_t*>(d.ref);
            } else {
                return false;
            }
        } else {
            return false;
        }
    }
    out.form = kArithmeticForms[output.aux];
    return true;
}

// The handlers, one function each so that the machine code can call them:
// what the power becomes, from the power before and the argument (the
// operand's address, the DecodedInstruction or a row, by handler).
#define RS_FAST_OP(kind)                                                                           \
    template <>                                                                                    \
    [[gnu::always_inline]] inline unsigned fastOp<kind>([[maybe_unused]] FastContext & c,          \
                                                        [[maybe_unused]] const void* arg,          \
                                                        [[maybe_unused]] unsigned power)
#define RS_IN (*static_cast<const DecodedInstruction*>(arg))
#define RS_BYTE (*static_cast<std::uint8_t*>(const_cast<void*>(arg)))
#define RS_NEGATED static_cast<unsigned>(RS_IN.flags & compiler::Negated)
#define RS_DITTO (c.unit->memory.systemMemories[kDitto])

RS_FAST_OP(FRung) {
    return 1;
}
RS_FAST_OP(FStart) {
    return RS_BYTE != 0;
}
RS_FAST_OP(FStartNot) {
    return RS_BYTE == 0;
}
RS_FAST_OP(FAnd) {
    return power & static_cast<unsigned>(RS_BYTE != 0);
}
RS_FAST_OP(FAndNot) {
    return power & static_cast<unsigned>(RS_BYTE == 0);
}
RS_FAST_OP(FContact) {
    return power & (static_cast<unsigned>(RS_IN.readBit()) ^ RS_NEGATED);
}
RS_FAST_OP(FEdge) {
    return power & c.unit->edge(RS_IN);
}
RS_FAST_OP(FEdgeStart) {
    return c.unit->edge(RS_IN);
}
RS_FAST_OP(FByteEdge) {
    return power & byteEdge(*static_cast<const ByteEdge*>(arg));
}
RS_FAST_OP(FByteEdgeStart) {
    return byteEdge(*static_cast<const ByteEdge*>(arg));
}
RS_FAST_OP(FContactRegisterBit) {
    return power &
           (((static_cast<unsigned>(*static_cast<const std::uint16_t*>(RS_IN.ref)) >> RS_IN.bit) &
             1u) ^
            RS_NEGATED);
}
RS_FAST_OP(FTimer) {
    return c.unit->timer(RS_IN, power != 0, c.cycleMs);
}
RS_FAST_OP(FLoadA) {
    c.a = RS_IN.readWord();
    return power;
}
RS_FAST_OP(FLoadAWord) {
    c.a = *static_cast<const std::int16_t*>(arg);
    return power;
}
RS_FAST_OP(FLoadAConstant) {
    c.a = *static_cast<const std::int32_t*>(arg);
    return power;
}
RS_FAST_OP(FLoadB) {
    c.b = RS_IN.readWord();
    return power;
}
RS_FAST_OP(FLoadBWord) {
    c.b = *static_cast<const std::int16_t*>(arg);
    return power;
}
RS_FAST_OP(FLoadBConstant) {
    c.b = *static_cast<const std::int32_t*>(arg);
    return power;
}
RS_FAST_OP(FEqual) {
    return power & (static_cast<unsigned>(compares(lang::CompareOp::Equal, c.a, c.b)) ^ RS_NEGATED);
}
RS_FAST_OP(FGreater) {
    return power &
           (static_cast<unsigned>(compares(lang::CompareOp::Greater, c.a, c.b)) ^ RS_NEGATED);
}
RS_FAST_OP(FLess) {
    return power & (static_cast<unsigned>(compares(lang::CompareOp::Less, c.a, c.b)) ^ RS_NEGATED);
}
RS_FAST_OP(FGreaterEqual) {
    return power &
           (static_cast<unsigned>(compares(lang::CompareOp::GreaterEqual, c.a, c.b)) ^ RS_NEGATED);
}
RS_FAST_OP(FLessEqual) {
    return power &
           (static_cast<unsigned>(compares(lang::CompareOp::LessEqual, c.a, c.b)) ^ RS_NEGATED);
}
RS_FAST_OP(FBranchOpen) {
    c.branches[c.depth++] = {power, 0};
    return power;
}
RS_FAST_OP(FBranchNext) {
    c.branches[c.depth - 1].any |= power;
    return c.branches[c.depth - 1].in;
}
RS_FAST_OP(FBranchClose) {
    return power | c.branches[--c.depth].any;
}
RS_FAST_OP(FCoilByte) {
    RS_BYTE = static_cast<std::uint8_t>(outputBit<Op::Coil>(power, RS_BYTE));
    RS_DITTO = static_cast<std::uint8_t>(power);
    return power;
}
RS_FAST_OP(FCoilByteRung) {
    fastOp<FCoilByte>(c, arg, power);
    return 1;
}
RS_FAST_OP(FCoil) {
    RS_IN.writeBit(outputBit<Op::Coil>(power, RS_IN.readBit()));
    RS_DITTO = static_cast<std::uint8_t>(power);
    return power;
}
RS_FAST_OP(FCoilRegisterBit) {
    auto& word = *static_cast<std::uint16_t*>(RS_IN.ref);
    const auto mask = static_cast<unsigned>(1u << RS_IN.bit);
    const unsigned bit = outputBit<Op::Coil>(power, (word & mask) != 0);
    word = static_cast<std::uint16_t>((word & ~mask) | (bit * mask));
    RS_DITTO = static_cast<std::uint8_t>(power);
    return power;
}
RS_FAST_OP(FSetByte) {
    RS_BYTE = static_cast<std::uint8_t>(outputBit<Op::Set>(power, RS_BYTE));
    RS_DITTO = static_cast<std::uint8_t>(power);
    return power;
}
RS_FAST_OP(FSetByteRung) {
    fastOp<FSetByte>(c, arg, power);
    return 1;
}
RS_FAST_OP(FSet) {
    if (power)
        RS_IN.writeBit(outputBit<Op::Set>(1, RS_IN.readBit()));
    RS_DITTO = static_cast<std::uint8_t>(power);
    return power;
}
RS_FAST_OP(FResetByte) {
    RS_BYTE = static_cast<std::uint8_t>(outputBit<Op::Reset>(power, RS_BYTE));
    RS_DITTO = static_cast<std::uint8_t>(power);
    return power;
}
RS_FAST_OP(FResetByteRung) {
    fastOp<FResetByte>(c, arg, power);
    return 1;
}
RS_FAST_OP(FReset) {
    if (power)
        RS_IN.writeBit(outputBit<Op::Reset>(1, RS_IN.readBit()));
    RS_DITTO = static_cast<std::uint8_t>(power);
    return power;
}
RS_FAST_OP(FToggle) {
    if (power)
        RS_IN.writeBit(outputBit<Op::Toggle>(1, RS_IN.readBit()));
    RS_DITTO = static_cast<std::uint8_t>(power);
    return power;
}
RS_FAST_OP(FJump) {
    if (power)
        *c.pendingJump = RS_IN.slot; // the last jump taken in the step wins
    return power;
}
RS_FAST_OP(FSequenceReset) {
    if (power && RS_IN.slot < 10)
        c.unit->sequences[RS_IN.slot].resetRequested = true;
    return power;
}
RS_FAST_OP(FArith) {
    if (power)
        c.unit->arithmetic(RS_IN, c.a, c.b);
    return power;
}
RS_FAST_OP(FArithRegister) {
    if (!power)
        return power;
    auto& target = *static_cast<std::int16_t*>(RS_IN.ref);
    const std::int64_t current = target;
    // translate() leaves divisions to UnitState::arithmetic().
    const std::int64_t result = kArithmeticForms[RS_IN.aux].undivided(current, c.a, c.b);
    c.unit->memory.systemMemories[kOverflow] = outside(result, kRegisterBounds);
    target = static_cast<std::int16_t>(saturated(result, kRegisterBounds));
    return power;
}
RS_FAST_OP(FSystem) {
    runSystemCall(*c.unit, RS_IN);
    return 1;
}
RS_FAST_OP(FBitStatements) {
    runBitStatements<true>(*static_cast<const Row<BitStatement>*>(arg), RS_DITTO, *c.pendingJump);
    return power;
}
RS_FAST_OP(FBitStatementsWithoutEdges) {
    runBitStatements<false>(*static_cast<const Row<BitStatement>*>(arg), RS_DITTO, *c.pendingJump);
    return power;
}
RS_FAST_OP(FWordStatements) {
    runWordStatements(*static_cast<const Row<WordStatement>*>(arg),
                      c.unit->memory.systemMemories[kOverflow], c.a, c.b);
    return power;
}
RS_FAST_OP(FEnd) {
    return power;
}

#undef RS_DITTO
#undef RS_NEGATED
#undef RS_BYTE
#undef RS_IN
#undef RS_FAST_OP

namespace {

template <int kind> unsigned fastCall(void* context, const void* arg, unsigned power) {
    return fastOp<kind>(*static_cast<FastContext*>(context), arg, power);
}

} // namespace

ScanMachineCode::Handler FastInterpreter::handler(FastHandler kind) {
    static constexpr auto calls = []<std::size_t... kinds>(std::index_sequence<kinds...>) {
        return std::array<ScanMachineCode::Handler, sizeof...(kinds)>{
            &fastCall<static_cast<int>(kinds)>...};
    }
    (std::make_index_sequence<FastHandlerCount>());
    return calls[kind];
}

const void* const* FastInterpreter::handlerAddresses() {
    const void* const* table = nullptr;
    int unused = 0;
    runOps(nullptr, nullptr, unused, 0, &table);
    return table;
}

void FastInterpreter::run(UnitState& unit, int index, int& pendingJump, int cycleMs) const {
    runOps(m_ops.data() + m_stepStart[static_cast<std::size_t>(index)], &unit, pendingJump,
           cycleMs);
}

// The handlers in a loop of their own, without the marks: threaded dispatch
// (GCC's labels as values), each handler jumping straight to the next one.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
void FastInterpreter::runOps(const FastOp* op, UnitState* unit, int& pendingJump, int cycleMs,
                             const void* const** handlerTable) {
    static const void* const handlers[] = {&&rung,
                                           &&start,
                                           &&startNot,
                                           &&and_,
                                           &&andNot,
                                           &&contact,
                                           &&edge,
                                           &&edgeStart,
                                           &&byteEdge,
                                           &&byteEdgeStart,
                                           &&contactRegisterBit,
                                           &&timer,
                                           &&loadA,
                                           &&loadAWord,
                                           &&loadAConstant,
                                           &&loadB,
                                           &&loadBWord,
                                           &&loadBConstant,
                                           &&equal,
                                           &&greater,
                                           &&less,
                                           &&greaterEqual,
                                           &&lessEqual,
                                           &&branchOpen,
                                           &&branchNext,
                                           &&branchClose,
                                           &&coilByte,
                                           &&coilByteRung,
                                           &&coil,
                                           &&coilRegisterBit,
                                           &&setByte,
                                           &&setByteRung,
                                           &&set,
                                           &&resetByte,
                                           &&resetByteRung,
                                           &&reset,
                                           &&toggle,
                                           &&jump,
                                           &&sequenceReset,
                                           &&arith,
                                           &&arithRegister,
                                           &&system,
                                           &&bitStatements,
                                           &&bitStatementsWithoutEdges,
                                           &&wordStatements,
                                           &&end};
    static_assert(std::size(handlers) == FastHandlerCount);
    if (handlerTable) {
        *handlerTable = handlers;
        return;
    }
    FastContext c = startContext(*unit, pendingJump, cycleMs);
    unsigned power = 1;
#define RS_RUN(kind)                                                                               \
    power = fastOp<kind>(c, op->arg, power);                                                       \
    goto*(++op)->handler

    goto * op->handler;
rung:
    RS_RUN(FRung);
start:
    RS_RUN(FStart);
startNot:
    RS_RUN(FStartNot);
and_:
    RS_RUN(FAnd);
andNot:
    RS_RUN(FAndNot);
contact:
    RS_RUN(FContact);
edge:
    RS_RUN(FEdge);
edgeStart:
    RS_RUN(FEdgeStart);
byteEdge:
    RS_RUN(FByteEdge);
byteEdgeStart:
    RS_RUN(FByteEdgeStart);
contactRegisterBit:
    RS_RUN(FContactRegisterBit);
timer:
    RS_RUN(FTimer);
loadA:
    RS_RUN(FLoadA);
loadAWord:
    RS_RUN(FLoadAWord);
loadAConstant:
    RS_RUN(FLoadAConstant);
loadB:
    RS_RUN(FLoadB);
loadBWord:
    RS_RUN(FLoadBWord);
loadBConstant:
    RS_RUN(FLoadBConstant);
equal:
    RS_RUN(FEqual);
greater:
    RS_RUN(FGreater);
less:
    RS_RUN(FLess);
greaterEqual:
    RS_RUN(FGreaterEqual);
lessEqual:
    RS_RUN(FLessEqual);
branchOpen:
    RS_RUN(FBranchOpen);
branchNext:
    RS_RUN(FBranchNext);
branchClose:
    RS_RUN(FBranchClose);
coilByte:
    RS_RUN(FCoilByte);
coilByteRung:
    RS_RUN(FCoilByteRung);
coil:
    RS_RUN(FCoil);
coilRegisterBit:
    RS_RUN(FCoilRegisterBit);
setByte:
    RS_RUN(FSetByte);
setByteRung:
    RS_RUN(FSetByteRung);
set:
    RS_RUN(FSet);
resetByte:
    RS_RUN(FResetByte);
resetByteRung:
    RS_RUN(FResetByteRung);
reset:
    RS_RUN(FReset);
toggle:
    RS_RUN(FToggle);
jump:
    RS_RUN(FJump);
sequenceReset:
    RS_RUN(FSequenceReset);
arith:
    RS_RUN(FArith);
arithRegister:
    RS_RUN(FArithRegister);
system:
    RS_RUN(FSystem);
bitStatements:
    RS_RUN(FBitStatements);
bitStatementsWithoutEdges:
    RS_RUN(FBitStatementsWithoutEdges);
wordStatements:
    RS_RUN(FWordStatements);
end:
    return;
#undef RS_RUN
}
#pragma GCC diagnostic pop

} // namespace rs::sim::engine
