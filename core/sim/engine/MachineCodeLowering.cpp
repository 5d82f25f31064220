// SPDX-License-Identifier: GPL-3.0-or-later
#include "MachineCodeLowering.h"

#include "FastInterpreter.h"
#include "InstructionMeaning.h"

#include <cstddef>

namespace rs::sim::engine {

namespace {

// The machine code's arithmetic takes x from one place (the target or a) and
// y from one (a constant, a or b): so does every form but the unknown one.
static_assert([] {
    for (std::size_t op = 0; op < kUnknownArithmetic; ++op) {
        const ArithmeticForm& f = kArithmeticForms[op];
        const bool oneX = f.fromCurrent + f.fromA == 1 && f.fromCurrent >= 0 && f.fromA >= 0;
        const int ys = (f.constant != 0) + (f.yA != 0) + (f.yB != 0);
        if (!oneX || ys > 1 || f.yA < -1 || f.yA > 1 || f.yB < -1 || f.yB > 1)
            return false;
    }
    return true;
}());

static_assert(static_cast<int>(ScanMachineCode::Condition::Equal) ==
                  static_cast<int>(lang::CompareOp::Equal) &&
              static_cast<int>(ScanMachineCode::Condition::Greater) ==
                  static_cast<int>(lang::CompareOp::Greater) &&
              static_cast<int>(ScanMachineCode::Condition::Less) ==
                  static_cast<int>(lang::CompareOp::Less) &&
              static_cast<int>(ScanMachineCode::Condition::GreaterEqual) ==
                  static_cast<int>(lang::CompareOp::GreaterEqual) &&
              static_cast<int>(ScanMachineCode::Condition::LessEqual) ==
                  static_cast<int>(lang::CompareOp::LessEqual));

// Register arithmetic other than a division, in line; false for the rest.
bool lowerArithmetic(const DecodedInstruction& d, ScanMachineCode::Run& run,
                     std::uint8_t& overflow) {
    using Operation = ScanMachineCode::Operation;
    constexpr auto a = static_cast<std::int32_t>(offsetof(FastContext, a));
    constexpr auto b = static_cast<std::int32_t>(offsetof(FastContext, b));
    const ArithmeticForm& form = kArithmeticForms[d.aux];
    if (!d.isWordKind(WordRef::Kind::Register) || d.dropWrite || d.aux == kUnknownArithmetic ||
        form.operation == ArithmeticForm::Operation::Divide)
        return false;
    ScanMachineCode::Instruction in{
        .kind = ScanMachineCode::Kind::Arithmetic, .place = d.ref, .state = &overflow};
    // x: the target's value or a; y: a constant, a or b, subtracted when negative.
    in.slot = form.fromCurrent ? ScanMachineCode::kCurrent : a;
    const int ySign = form.yA + form.yB;
    in.slot2 = form.yA ? a : form.yB ? b : ScanMachineCode::kConstant;
    in.constant = form.constant;
    in.operation = form.operation == ArithmeticForm::Operation::Multiply ? Operation::Multiply
                   : ySign < 0                                           ? Operation::Subtract
                                                                         : Operation::Add;
    run.push_back(in);
    return true;
}

} // namespace

std::unique_ptr<ScanMachineCode> lowerToMachineCode(UnitState& unit) {
    using Kind = ScanMachineCode::Kind;
    using Instruction = ScanMachineCode::Instruction;
    static_assert(offsetof(EdgeState, seen) == 0 && offsetof(EdgeState, last) == 1);
    static_assert(offsetof(FastContext::Branch, any) == 4);
    constexpr auto slotA = static_cast<std::int32_t>(offsetof(FastContext, a));
    constexpr auto slotB = static_cast<std::int32_t>(offsetof(FastContext, b));
    constexpr int maxDepth = FastContext::kMaxDepth;
    std::uint8_t* ditto = &unit.memory.systemMemories[kDitto];
    std::vector<ScanMachineCode::Run> runs;
    runs.reserve(unit.steps.size());
    for (const StepRun& step : unit.steps) {
        ScanMachineCode::Run& run = runs.emplace_back();
        int depth = 0;
        for (std::uint32_t i = step.first; i < step.first + step.count; ++i) {
            const DecodedInstruction& d = unit.code[i];
            const bool negated = d.flags & compiler::Negated;
            const bool byte = d.refKind == static_cast<std::uint8_t>(BitRef::Kind::Byte);
            const bool registerBit =
                d.refKind == static_cast<std::uint8_t>(BitRef::Kind::RegisterBit);
            // A register bit is a bit of one of its bytes (x86-64 is little-endian).
            const auto bitPlace = [&](Kind kind) {
                Instruction in{.kind = kind, .negated = negated, .place = d.ref};
                if (registerBit) {
                    in.place = static_cast<const std::uint8_t*>(d.ref) + d.bit / 8;
                    in.mask = static_cast<std::uint8_t>(1u << (d.bit % 8));
                }
                return in;
            };
            const auto call = [&](FastHandler handler) {
                run.push_back({.kind = Kind::Call,
                               .handler = FastInterpreter::handler(handler),
                               .place = &d});
            };
            const auto output = [&](Kind kind, FastHandler otherwise) {
                if (byte || registerBit) {
                    run.push_back(bitPlace(kind));
                    run.push_back({.kind = Kind::Store, .place = ditto});
                } else {
                    call(otherwise);
                }
            };
            switch (static_cast<Handler>(d.handler)) {
            case HRung:
                run.push_back({.kind = Kind::Rung});
                break;
            case HContactByte:
            case HContact:
                if (byte || registerBit)
                    run.push_back(bitPlace(Kind::And));
                else
                    call(FContact);
                break;
            case HEdge:
                if (byte || registerBit) {
                    Instruction in = bitPlace(Kind::Edge);
                    in.rising = d.flags & compiler::Rising;
                    in.operandNegated = d.flags & compiler::OperandNegated;
                    in.state = &unit.edges[d.slot];
                    run.push_back(in);
                } else {
                    call(FEdge);
                }
                break;
            case HTimer:
                call(FTimer);
                break;
            case HLoadA:
            case HLoadB: {
                const std::int32_t slot = d.handler == HLoadA ? slotA : slotB;
                if (d.flags & compiler::ConstantOperand)
                    run.push_back({.kind = Kind::LoadConst, .slot = slot, .constant = d.constant});
                else if (d.refKind == static_cast<std::uint8_t>(WordRef::Kind::Register))
                    run.push_back({.kind = Kind::Load, .slot = slot, .place = d.ref});
                else
                    call(d.handler == HLoadA ? FLoadA : FLoadB);
                break;
            }
            case HEqual:
            case HGreater:
            case HLess:
            case HGreaterEqual:
            case HLessEqual:
                run.push_back(
                    {.kind = Kind::Compare,
                     .negated = negated,
                     .condition = static_cast<ScanMachineCode::Condition>(d.handler - HEqual),
                     .slot = slotA,
                     .slot2 = slotB});
                break;
            case HBranchOpen:
            case HBranchNext:
            case HBranchClose: {
                if (d.handler == HBranchOpen)
                    ++depth;
                if (depth < 1 || depth > maxDepth)
                    return nullptr; // not a program the compiler makes: interpreted
                const auto slot = static_cast<std::int32_t>(
                    offsetof(FastContext, branches) +
                    sizeof(FastContext::Branch) * static_cast<std::size_t>(depth - 1));
                const Kind kind = d.handler == HBranchOpen   ? Kind::Open
                                  : d.handler == HBranchNext ? Kind::Next
                                                             : Kind::Close;
                run.push_back({.kind = kind, .slot = slot});
                if (d.handler == HBranchClose)
                    --depth;
                break;
            }
            case HCoilByte:
            case HCoil:
                output(Kind::Store, FCoil);
                break;
            case HSetByte:
            case HSet:
                output(Kind::Set, FSet);
                break;
            case HResetByte:
            case HReset:
                output(Kind::Reset, FReset);
                break;
            case HToggle:
                call(FToggle);
                break;
            case HJump:
                call(FJump);
                break;
            case HSequenceReset:
                call(FSequenceReset);
                break;
            case HArith:
                if (!lowerArithmetic(d, run, unit.memory.systemMemories[kOverflow]))
                    call(FArith);
                break;
            case HSystem:
                call(FSystem);
                break;
            case HArgument:
                break; // FSystem reads it
            case HandlerCount:
                break;
            }
        }
    }
    return ScanMachineCode::compile(runs, &unit.memory);
}

} // namespace rs::sim::engine
