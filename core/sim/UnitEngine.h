#pragma once

#include "ScanMachineCode.h"
#include "Timer.h"
#include "UnitMemory.h"
#include "compiler/Image.h"

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace rs::sim {

// Per instruction, what the last scan did: not run (its step was not
// active), run with the power off after it, or run with the power on.
enum class Conduction : std::uint8_t { NotRun = 0, Off = 1, On = 2 };

// Runs one unit's compiled image, scan by scan, on virtual time. It reads
// other units' global variables from the bus image it is given, as they were
// at the start of the scan, never from their live memory.
class UnitEngine {
public:
    using Bus = std::array<UnitMemory, 32>;

    UnitEngine(compiler::UnitImage image, const Bus& published);

    // Power on: every variable 0 except the remanent ones listed (R100..R131,
    // M100..M131 as configured), sequences in step 0, timers and edges fresh,
    // the next scan is the first (SM_SysInit).
    void powerOn(const std::vector<lang::Address>& keep = {});

    // One scan at virtual time `timeMs`, `cycleMs` after the previous one.
    void scan(std::int64_t timeMs, int cycleMs);

    const compiler::UnitImage& image() const { return m_image; }
    UnitMemory& memory() { return m_memory; }
    const UnitMemory& memory() const { return m_memory; }
    int activeStep(int sequence) const;
    bool hasSequence(int sequence) const;
    // What each instruction did in the last scan. A scan runs without marking
    // conduction; the first call after it runs that scan again, marking, from
    // the state the scan started with (docs/simulator.md, "What a scan
    // reports"), so, like scan(), it must not run alongside another call.
    const std::vector<Conduction>& conduction() const;
    // Marks conduction while scanning instead, for callers that read it after
    // every scan.
    void setEagerConduction(bool eager);
    bool eagerConduction() const { return m_eagerConduction; }
    // The state of timer occurrence `slot` (Instruction::slot of a Timer), to show its elapsed
    // time.
    const Timer& timer(std::size_t slot) const { return m_timers[slot]; }

    // The units on the bus, for SM_Pluto0_Present .. SM_Pluto31_Present.
    void setPresent(const std::array<bool, 32>& present);

    // A forced variable keeps its value: the program's writes to it are dropped.
    void force(const lang::Address& address, std::int64_t value);
    void release(const lang::Address& address);
    const std::map<lang::Address, std::int64_t>& forces() const { return m_forces; }

    // Reads and writes a variable of this unit as a scenario or the GUI does.
    std::int64_t read(const lang::Address& address) const;
    void write(const lang::Address& address, std::int64_t value);

private:
    // An instruction ready to run: 24 bytes, its operand resolved to a pointer
    // into this unit's memory (or the bus image, or a sink for forced targets).
    struct Decoded {
        compiler::Op op;
        std::uint8_t handler; // what runStep does, specialised by operand kind
        std::uint8_t flags;
        std::uint8_t aux;
        std::uint8_t refKind; // BitRef::Kind or WordRef::Kind, by op
        std::uint8_t bit;     // register bit
        bool dropWrite;       // an arithmetic target that is forced
        std::uint16_t slot;
        std::int32_t constant;
        void* ref;

        void pointAt(const BitRef& target);
        void pointAt(const WordRef& target);
        bool readBit() const;
        void writeBit(bool value) const;
        std::int64_t readWord() const;
        void writeWord(std::int64_t value) const;
        bool wideWord() const;
    };
    // The unmarked form of a step's code: handlers jump to each other
    // directly, a Rung is folded into its neighbours, and an end marker
    // closes the step. `arg` is the operand's address or the Decoded entry.
    struct FastOp {
        const void* handler;
        void* arg;
    };
    struct StepRun {
        int sequence;
        int step;
        std::uint32_t first;
        std::uint32_t count;
        std::uint32_t fastFirst;
    };
    struct SequenceState {
        int active = 0;
        bool stepNew = true;
        bool resetRequested = false;
    };
    struct Sequence : SequenceState {
        std::vector<int> stepIndex; // step number -> index in m_steps, -1 when absent
    };
    struct EdgeState {
        bool seen = false;
        bool last = false;
    };
    // An edge on a byte operand, all runFast needs at hand.
    struct ByteEdge {
        const std::uint8_t* operand;
        EdgeState* state;
        std::uint8_t operandNegated;
        std::uint8_t rising;
        std::uint8_t negated;
    };
    // A statement of at most two contacts and one edge in series, on bytes or
    // register bits, and one output (=, S, R, T on a byte or register bit, or
    // a jump): runFast runs a row of them as a loop without a branch that
    // depends on the program or the data. A bit is (*read & mask) != 0;
    // unused contacts read a 1, an unused edge is a negated one that never
    // fires.
    struct BitStatement {
        const std::uint8_t* read[3]; // two contacts, the edge's operand
        EdgeState* edge;
        std::uint8_t* target;
        std::uint8_t mask[3];
        std::uint8_t negated[3]; // the contacts; the edge's operand (P(/x))
        std::uint8_t edgeRising;
        std::uint8_t edgeNegated;
        std::uint8_t targetMask; // the bits of *target that are the output
        std::uint8_t targetOne;  // the output's 1 (1 for a byte, the bit for a register bit)
        std::uint8_t keepOn;     // with power: output = (output & keepOn) ^ flipOn
        std::uint8_t flipOn;
        std::uint8_t keepOff; // without: *target &= keepOff
        std::uint8_t jump;    // 1: a jump to jumpStep with power, no output
        std::uint8_t jumpStep;
    };
    // A statement of at most one contact and one edge in series, a load of a
    // and of b, and arithmetic on a register other than a division: like a
    // BitStatement, runFast runs a row of them without branches. The result is
    // x + y or x * y with x = current * fromCurrent + a * fromA and
    // y = yConstant + yA * a + yB * b. A load reads 4 bytes (a 32-bit value, a
    // double register or a constant) and keeps the low 32 - narrow bits.
    struct WordStatement {
        const std::uint8_t* read[2]; // the contact, the edge's operand
        EdgeState* edge;
        const std::uint8_t* load[2];
        std::int16_t* target;
        std::uint8_t mask[2];
        std::uint8_t negated[2];
        std::uint8_t edgeRising;
        std::uint8_t edgeNegated;
        std::uint8_t loads[2]; // whether it loads a, b
        std::uint8_t narrow[2];
        std::int8_t fromCurrent;
        std::int8_t fromA;
        std::int8_t yConstant;
        std::int8_t yA;
        std::int8_t yB;
        std::uint8_t multiply;
    };
    // Consecutive statements of one kind, run by one handler.
    template <typename Statement> struct Row {
        const Statement* first;
        const Statement* end;
    };
    // Everything the steps of a scan read and write besides the code: what a
    // replay of the scan starts from.
    struct ScanState {
        UnitMemory memory;
        std::vector<EdgeState> edges;
        std::vector<Timer> timers;
        std::array<SequenceState, 10> sequences;
        std::uint64_t scan = 0;
        int cycleMs = 0;
    };
    // Another unit's variable that this unit reads: copied from the bus at the
    // start of each scan, so that a replay sees what the scan saw.
    struct RemoteCopy {
        std::uint8_t* to;
        const std::uint8_t* from;
        std::size_t size;
    };
    void decode();
    void translate();
    bool toBitStatement(std::uint32_t first, std::uint32_t end, BitStatement& out);
    bool toWordStatement(std::uint32_t first, std::uint32_t end, WordStatement& out);
    void runWordStatements(const Row<WordStatement>& row, std::int64_t& a, std::int64_t& b);
    template <bool withEdges>
    static void runBitStatements(const Row<BitStatement>& row, std::uint8_t& ditto, int& jump);
    // What a step's unmarked code works on besides the power: runFast's
    // locals, or the context the step's machine code passes its handlers.
    struct FastContext {
        struct Branch {
            unsigned in;
            unsigned any;
        };
        UnitEngine* engine;
        int* pendingJump;
        int cycleMs;
        int depth;
        std::int64_t a;
        std::int64_t b;
        Branch branches[64];
    };
    // runFast's handler `kind`: inlined there, and called by the machine code
    // as fastCall<kind>.
    template <int kind>
    static unsigned fastOp(FastContext& context, const void* arg, unsigned power);
    template <int kind> static unsigned fastCall(void* context, const void* arg, unsigned power);
    // Translates each step's code to machine code without marks, where the
    // machine allows it (docs/simulator.md, "Speed").
    void compileSteps();
    bool compileArithmetic(const Decoded& in, ScanMachineCode::Run& run);
    void runSteps(bool marking, int cycleMs);
    // Runs a step's unmarked code from `op`; with `handlerTable`, only gives
    // the handlers' addresses for translate() and runs nothing.
    void runFast(const FastOp* op, int& pendingJump, int cycleMs,
                 const void* const** handlerTable = nullptr);
    unsigned edge(const Decoded& in);
    static unsigned byteEdge(const ByteEdge& edge);
    void save(ScanState& state) const;
    void restore(const ScanState& state);
    void replay();
    static std::uint8_t handlerFor(const Decoded& decoded);
    UnitMemory& remoteCopy(int station);
    template <typename Ref>
    Ref readRemote(const lang::Address& address, Ref (*locate)(UnitMemory&, const lang::Address&));
    BitRef decodeBit(const lang::Address& address, bool forWriting);
    WordRef decodeWord(const lang::Address& address);
    void runStep(int index, int& pendingJump, int cycleMs);
    bool timer(const Decoded& in, bool input, int cycleMs);
    void arithmetic(const Decoded& in, std::int64_t a, std::int64_t b);
    void leaveStep(int index);
    void applyForces();

    compiler::UnitImage m_image;
    const Bus& m_bus;
    UnitMemory m_memory;
    UnitMemory m_sink;                                    // where writes to forced variables go
    std::array<std::unique_ptr<UnitMemory>, 32> m_remote; // other units' variables as last read
    std::vector<RemoteCopy> m_remoteCopies;
    std::vector<Decoded> m_code;
    std::vector<FastOp> m_fast;
    std::unique_ptr<ScanMachineCode> m_machineCode; // a run per step, or null: runFast
    std::vector<ByteEdge> m_byteEdges;
    std::vector<BitStatement> m_bitStatements;
    std::vector<Row<BitStatement>> m_bitStatementRows;
    std::vector<WordStatement> m_wordStatements;
    std::vector<Row<WordStatement>> m_wordStatementRows;
    EdgeState m_noEdge; // what an unused edge of a BitStatement works on
    std::vector<StepRun> m_steps;
    std::array<Sequence, 10> m_sequences;
    std::vector<EdgeState> m_edges;
    std::vector<Timer> m_timers;
    mutable std::vector<Conduction> m_conduction;
    ScanState m_scanStart;            // the state the last scan's steps started from
    mutable bool m_replayDue = false; // m_conduction is not yet that of the last scan
    bool m_eagerConduction = false;
    std::vector<int> m_ranSteps; // steps run in the last scan, by index
    std::map<lang::Address, std::int64_t> m_forces;
    std::array<bool, 32> m_present{};
    std::uint64_t m_scan = 0;
};

} // namespace rs::sim
