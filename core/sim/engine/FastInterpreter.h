// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ScanMachineCode.h"
#include "StatementRows.h"
#include "UnitState.h"

#include <cstdint>
#include <vector>

namespace rs::sim::engine {

// The fast interpreter's handlers.
enum FastHandler : std::uint8_t {
    FRung,
    FStart, // a rung and a contact on a byte
    FStartNot,
    FAnd, // a contact on a byte
    FAndNot,
    FContact,
    FEdge,
    FEdgeStart, // a rung and an edge
    FByteEdge,
    FByteEdgeStart,
    FContactRegisterBit,
    FTimer,
    FLoadA,
    FLoadAWord,
    FLoadAConstant,
    FLoadB,
    FLoadBWord,
    FLoadBConstant,
    FEqual, // FEqual + lang::CompareOp
    FGreater,
    FLess,
    FGreaterEqual,
    FLessEqual,
    FBranchOpen,
    FBranchNext,
    FBranchClose,
    FCoilByte,
    FCoilByteRung, // a coil on a byte and the next statement's rung
    FCoil,
    FCoilRegisterBit,
    FSetByte,
    FSetByteRung,
    FSet,
    FResetByte,
    FResetByteRung,
    FReset,
    FToggle,
    FJump,
    FSequenceReset,
    FArith,
    FArithRegister, // on a register, not a division
    FSystem,        // a system instruction; its Arguments have no handler of their own
    FBitStatements, // a row of BitStatements
    FBitStatementsWithoutEdges,
    FWordStatements, // a row of WordStatements
    FEnd,
    FastHandlerCount
};

// What a step's unmarked code works on besides the power: the fast
// interpreter's locals, or the context a step's machine code passes its
// handlers (which is why its layout is the machine code's business too).
struct FastContext {
    static constexpr int kMaxDepth = 64; // parallel branches open at once
    struct Branch {
        unsigned in;
        unsigned any;
    };
    UnitState* unit;
    int* pendingJump;
    int cycleMs;
    int depth;
    std::int64_t a;
    std::int64_t b;
    Branch branches[kMaxDepth]; // written before they are read: left uninitialised
};

// An edge on a byte operand, all the edge handler needs at hand.
struct ByteEdge {
    const std::uint8_t* operand;
    EdgeState* state;
    std::uint8_t operandNegated;
    std::uint8_t rising;
    std::uint8_t negated;
};

inline FastContext startContext(UnitState& unit, int& pendingJump, int cycleMs) {
    FastContext context;
    context.unit = &unit;
    context.pendingJump = &pendingJump;
    context.cycleMs = cycleMs;
    context.depth = 0;
    context.a = 0;
    context.b = 0;
    return context;
}

// The unmarked form of a unit's steps: consecutive simple statements become
// rows (StatementRows.h), the others run instruction by instruction through
// threaded handlers, a statement's Rung folded into its neighbours, and an end
// marker closes each step. A scan that nobody looks at in detail costs what
// its logic costs.
class FastInterpreter {
public:
    // Translates the unit's decoded code; again whenever it is decoded again.
    // The result points into `unit`, which must stay where it is.
    void translate(UnitState& unit);
    void run(UnitState& unit, int index, int& pendingJump, int cycleMs) const;

    // Handler `kind` as a function, for the machine code to call with a
    // FastContext and the instruction (DecodedInstruction*) as argument.
    static ScanMachineCode::Handler handler(FastHandler kind);

private:
    // `arg` is the operand's address, the DecodedInstruction or a row, by handler.
    struct FastOp {
        const void* handler;
        void* arg;
    };
    static const void* const* handlerAddresses();
    // Runs from `op` to the step's end; with `handlerTable`, only gives the
    // handlers' addresses and runs nothing.
    static void runOps(const FastOp* op, UnitState* unit, int& pendingJump, int cycleMs,
                       const void* const** handlerTable = nullptr);
    bool toBitStatement(UnitState& unit, std::uint32_t first, std::uint32_t end, BitStatement& out);
    bool toWordStatement(UnitState& unit, std::uint32_t first, std::uint32_t end,
                         WordStatement& out);

    std::vector<FastOp> m_ops;
    std::vector<std::uint32_t> m_stepStart; // by step index, in m_ops
    std::vector<ByteEdge> m_byteEdges;
    std::vector<BitStatement> m_bitStatements;
    std::vector<Row<BitStatement>> m_bitStatementRows;
    std::vector<WordStatement> m_wordStatements;
    std::vector<Row<WordStatement>> m_wordStatementRows;
    EdgeState m_noEdge; // what an unused edge of a statement in a row works on
};

} // namespace rs::sim::engine
