#pragma once

#include "Timer.h"
#include "UnitMemory.h"
#include "compiler/Image.h"

#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace rs::sim {

// Per instruction, what the last scan did: not run (its step was not
// active), run with the power off after it, or run with the power on.
enum class Conduction : std::uint8_t { NotRun = 0, Off = 1, On = 2 };

// Runs one unit's compiled image, scan by scan, on virtual time. It reads
// other units' global variables from the bus image it is given, never from
// their live memory.
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
    const std::vector<Conduction>& conduction() const { return m_conduction; }
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
    struct StepRun {
        int sequence;
        int step;
        std::uint32_t first;
        std::uint32_t count;
    };
    struct Sequence {
        std::vector<int> stepIndex; // step number -> index in m_steps, -1 when absent
        int active = 0;
        bool stepNew = true;
        bool resetRequested = false;
    };
    struct EdgeState {
        bool seen = false;
        bool last = false;
    };
    void decode();
    static std::uint8_t handlerFor(const Decoded& decoded);
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
    UnitMemory m_sink; // where writes to forced variables go
    std::vector<Decoded> m_code;
    std::vector<StepRun> m_steps;
    std::array<Sequence, 10> m_sequences;
    std::vector<EdgeState> m_edges;
    std::vector<Timer> m_timers;
    std::vector<Conduction> m_conduction;
    std::vector<int> m_ranSteps; // steps run in the last scan, by index
    std::map<lang::Address, std::int64_t> m_forces;
    std::array<bool, 32> m_present{};
    std::uint64_t m_scan = 0;
};

} // namespace rs::sim
