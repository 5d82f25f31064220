// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

namespace rs::sim::engine {

// Machine code for straight runs of a scan's instructions, made at load
// time. The common instructions (contacts, edges, coils, parallel branches,
// loads, comparisons, register arithmetic) become a few machine instructions
// in line, without a jump; the others a call of their handler (call
// threading). So the processor has nothing to predict but those calls, where
// an interpreter's dispatch jumps outgrow its branch predictor on a large
// project (docs/simulator.md, "Speed").
class ScanMachineCode {
public:
    // A handler gets the context the run was started with, its argument and
    // the power (0 or 1), and returns the power.
    using Handler = unsigned (*)(void* context, const void* argument, unsigned power);
    using Entry = void (*)(void* context);

    // `byte`, `word`: the place; `slot`: a 64-bit value in the context, at that offset.
    enum class Kind : std::uint8_t {
        Call,       // power = handler(context, place, power)
        Rung,       // power = 1
        And,        // power &= ((*byte & mask) != 0) ^ negated
        Edge,       // power &= edge of And's bit seen, ^ negated (state: seen, last bytes)
        Store,      // the bits `mask` of *byte = power (a whole byte: power)
        Set,        // the bits `mask` of *byte |= power
        Reset,      // the bits `mask` of *byte &= !power
        Load,       // slot = *word (16 bits, signed)
        LoadConst,  // slot = constant
        Compare,    // power &= (slot <condition> slot2) ^ negated
        Open,       // a parallel branch at slot (32 bits power in, 32 bits any)
        Next,       // any |= power, power = in
        Close,      // power |= any
        Arithmetic, // if power: *word = saturated(x <operation> y), *state = overflow
                    // (InstructionMeaning.h)
    };
    enum class Condition : std::uint8_t { Equal, Greater, Less, GreaterEqual, LessEqual };
    enum class Operation : std::uint8_t { Add, Subtract, Multiply };
    static constexpr std::int32_t kCurrent = -1;  // Arithmetic's x: the target's value
    static constexpr std::int32_t kConstant = -1; // Arithmetic's y: the constant

    struct Instruction {
        Kind kind = Kind::Rung;
        std::uint8_t mask = 0xFF;
        bool negated = false;
        bool rising = false;         // an Edge's direction
        bool operandNegated = false; // an Edge of the bit's negation
        Condition condition = Condition::Equal;
        Operation operation = Operation::Add;
        std::int32_t slot = 0;  // Arithmetic: x
        std::int32_t slot2 = 0; // Arithmetic: y
        std::int32_t constant = 0;
        Handler handler = nullptr;
        const void* place = nullptr; // the handler's argument, the byte, the word
        void* state = nullptr;       // an Edge's state, Arithmetic's overflow flag
    };
    using Run = std::vector<Instruction>;

    // Null where there is no code generator for this machine (only x86-64
    // has one), when the system refuses executable memory, or when the
    // environment variable RUNGSMITH_NO_JIT is 1: the caller interprets
    // instead. Each run starts with the power 1. Places near `near` (most
    // of them) take shorter instructions.
    static std::unique_ptr<ScanMachineCode> compile(const std::vector<Run>& runs, const void* near);

    ScanMachineCode(const ScanMachineCode&) = delete;
    ScanMachineCode& operator=(const ScanMachineCode&) = delete;
    ~ScanMachineCode();

    Entry entry(std::size_t run) const { return m_entries[run]; }

private:
    struct Memory;
    ScanMachineCode();

    std::unique_ptr<Memory> m_memory;
    std::vector<Entry> m_entries;
};

} // namespace rs::sim::engine
