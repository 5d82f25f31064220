// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Address.h"

#include <cstdint>
#include <string>
#include <vector>

// The compiled program of one unit: what the simulator runs. Its byte layout
// is documented in docs/image-format.md.
namespace rs::compiler {

// One-operand instructions on a "power" bit that flows left to right through
// a statement, as through a rung: series elements AND into it, parallel
// branches save and combine it. A timer takes the power at its left as its
// input and gives its output to the right, which is the language's rule.
enum class Op : std::uint8_t {
    Rung = 1,      // power = 1: a statement starts
    Contact,       // power &= bit(operand) ^ negated
    Edge,          // power &= edge seen by this occurrence (slot) ^ negated
    Timer,         // timer slot: input = power; power = output (negated: input and not output)
    LoadA,         // a = word(operand) or constant
    LoadB,         // b = word(operand) or constant
    Compare,       // power &= (a <op> b) ^ negated
    BranchOpen,    // push {in = power, any = 0}
    BranchNext,    // any |= power; power = in
    BranchClose,   // power = any | power; pop
    Coil,          // bit(operand) = power
    Set,           // if power: bit(operand) = 1
    Reset,         // if power: bit(operand) = 0
    Toggle,        // if power: bit(operand) = !bit(operand)
    Jump,          // if power: the sequence goes to step `slot` at the end of its part of the scan
    SequenceReset, // if power: sequence `slot` is held in step 0
    Arith,         // if power: word(operand) = f(word(operand), a, b); f = aux
    System,        // power = 1; system instruction `aux` runs on the `slot` Arguments after it
    Argument,      // an operand of the System before it (aux: ArgumentRole); does nothing itself
};

// What a system instruction does with an Argument (its aux).
enum ArgumentRole : std::uint8_t {
    ArgumentWritten = 1, // an output; else an input
    ArgumentWord = 2,    // a number (a register, a double register, a constant); else a bit
};

// The statement number of a System and its Arguments: a system call is no
// statement of the language, so it takes none of their numbers.
inline constexpr std::uint32_t kNoStatement = 0xFFFFFFFF;

enum class ArithOp : std::uint8_t {
    Increment,
    Decrement,
    Add,
    Sub,
    Mul,
    Div,
    Copy,
    AddAB,
    SubAB,
    MulAB,
    DivAB
};

enum InstructionFlag : std::uint8_t {
    Negated = 1,         // Contact, Edge, Timer, Compare
    OperandNegated = 2,  // Edge of a negated operand: P(/x)
    Rising = 4,          // Edge: P (set) or N
    ConstantOperand = 8, // LoadA, LoadB, Timer, Argument: use `constant`, not `operand`
};

struct Instruction {
    Op op = Op::Rung;
    std::uint8_t flags = 0;
    // Timer: lang::TimerKind; Compare: lang::CompareOp; Arith: ArithOp; System:
    // SystemInstructionId; Argument: ArgumentRole
    std::uint8_t aux = 0;
    // Edge/Timer: occurrence number; Jump: step; SequenceReset: sequence;
    // System: how many Arguments follow
    std::uint16_t slot = 0;
    // Where it came from: the statement's line and column, the statement's
    // number in the unit (from 0, in file order) and the element within it
    // (0 the output, then the expression's nodes in pre-order from 1). The
    // two-byte fields lie together: 40 bytes an instruction, not 44.
    std::uint16_t column = 0;
    std::uint16_t element = 0;
    lang::Address operand;
    std::int32_t constant = 0;
    std::uint32_t line = 0;
    std::uint32_t statement = 0;

    friend bool operator==(const Instruction&, const Instruction&) = default;
};

// The code of one step: instructions [first, first + count).
struct StepCode {
    std::uint8_t sequence = 0; // 0 is the PLC code
    std::uint8_t step = 0;
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    friend bool operator==(const StepCode&, const StepCode&) = default;
};

// How a unit's declaration sets up one terminal ("! I0.5,c_pulse,non_inv"):
// part of what the unit does, as its code is.
struct TerminalSetup {
    // Each has its own numbering: I, Q and IQ terminals; the safety outputs
    // (Q2, Q3); the IA inputs.
    enum Group : std::uint8_t { Terminal, SafetyOutput, Analogue } group = Terminal;
    lang::AddressKind kind = lang::AddressKind::Input; // Input, Output, InputOutput, AnalogInput
    std::uint16_t number = 0;
    std::vector<std::string> options; // sorted: their order in the declaration means nothing

    friend bool operator==(const TerminalSetup&, const TerminalSetup&) = default;
};

// One defined slave of the AS-i Options page (project::AsiSlave in numbers).
struct AsiSlaveSetup {
    std::uint8_t number = 1; // 1-31
    bool b = false;
    std::uint8_t type = 0;  // project::AsiSlaveType, never Undefined
    std::uint8_t model = 0; // index in project::asiSafeInputModels()
    std::uint8_t parameter = 0xF;
    std::uint8_t profile[4] = {0, 0xB, 0xF, 0xF}; // I/O configuration, ID code, ID2, ID1
    std::uint8_t monitoring = 0;                  // project::ChannelMonitoring
    std::uint32_t timeLimitMs = 0;

    friend bool operator==(const AsiSlaveSetup&, const AsiSlaveSetup&) = default;
};

// How an AS-i unit works on its AS-i bus (manual Part 1, 7.1); all zero and
// no slaves for the defaults and for every other unit type.
struct AsiSetup {
    std::uint8_t mode = 0;             // project::AsiMode
    std::uint8_t optimisation = 0;     // project::AsiOptimisation
    std::uint8_t slaveAddress = 0;     // in the monitor/slave modes, else 0
    std::vector<AsiSlaveSetup> slaves; // by number, A before B

    friend bool operator==(const AsiSetup&, const AsiSetup&) = default;
};

// One External Comm Block of the unit's External communication setting
// (project::ExternalCommBlock in numbers).
struct ExternalCommSetup {
    std::uint8_t block = 0;   // 0-3
    std::uint8_t gateway = 0; // node address 0-15
    std::uint8_t packet = 0;  // 0-3
    std::uint16_t timeoutMs = 0;

    friend bool operator==(const ExternalCommSetup&, const ExternalCommSetup&) = default;
};

struct UnitImage {
    // Descriptive: they name the source, and change with its text.
    std::string projectName;
    std::uint32_t sourceCrc = 0;        // CRC-32 of the project's canonical text
    std::uint32_t projectSignature = 0; // of every unit of the project (Signature.h)
    // What decides the behaviour, which the unit's signature covers.
    std::uint8_t station = 0;
    std::uint8_t unitType = 0; // target::UnitType
    std::uint8_t instructionSet = 2;
    std::uint16_t timers = 0;
    std::uint16_t edges = 0;
    std::vector<StepCode> steps; // the PLC code first, then sequences by number and steps by number
    std::vector<Instruction> code;
    std::vector<TerminalSetup> terminals; // by group, then number
    std::vector<lang::Address> exported;  // the manual's [E], in address order
    std::vector<lang::Address> remanent;  // the manual's [R] of this unit, in address order
    AsiSetup asi;
    // The CAN bus cycle time set on the unit page (Part 1, 5.2), in ms; 0 the default.
    std::uint16_t canCycleMs = 0;
    // The External communication setting (Part 1, 5.3), by block.
    std::vector<ExternalCommSetup> externalComm;
    // Descriptive again.
    std::string source; // the canonical project text when "include source" is set, else empty

    friend bool operator==(const UnitImage&, const UnitImage&) = default;
};

} // namespace rs::compiler
