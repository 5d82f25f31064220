// SPDX-License-Identifier: GPL-3.0-or-later
#include "UnitEngine.h"

#include "engine/FastInterpreter.h"
#include "engine/MachineCodeLowering.h"
#include "engine/MarkingInterpreter.h"
#include "engine/OperandDecoder.h"
#include "engine/ScanMachineCode.h"
#include "engine/UnitState.h"
#include "lang/Ast.h"

#include <algorithm>
#include <utility>

namespace rs::sim {

namespace {

using lang::AddressKind;

constexpr int kStepNew = 0;
constexpr int kFlash = 2;
constexpr int k1Hz = 3;
constexpr int k10Hz = 4;
constexpr int kFastFlash = 5;
constexpr int kDoubleFlash = 6;
constexpr int kSysInit = 9;
constexpr int kSupplyVoltage = 40;

// The manual's flashing memories, as functions of virtual time.
bool flashing(int memory, std::int64_t t) {
    switch (memory) {
    case kFlash:
        return t % 1000 < 400;
    case k1Hz:
        return t % 1000 < 500;
    case k10Hz:
        return t % 100 < 50;
    case kFastFlash:
        return t % 500 < 170;
    case kDoubleFlash: {
        const std::int64_t phase = t % 1090;
        return phase < 110 || (phase >= 310 && phase < 420);
    }
    default:
        return false;
    }
}

} // namespace

namespace scan_replay {

// Everything the steps of a scan read and write besides the code: what a
// replay of the scan starts from. Not file-local: UnitEngine::Tiers holds one.
struct ScanState {
    UnitMemory memory;
    std::vector<engine::EdgeState> edges;
    std::vector<Timer> timers;
    std::array<engine::SequenceState, 10> sequences;
    std::uint64_t scan = 0;
    int cycleMs = 0;
};

static void save(const engine::UnitState& unit, ScanState& state) {
    state.memory = unit.memory;
    state.edges = unit.edges;
    state.timers = unit.timers;
    for (std::size_t i = 0; i < unit.sequences.size(); ++i)
        state.sequences[i] = unit.sequences[i];
    state.scan = unit.scan;
}

static void restore(engine::UnitState& unit, const ScanState& state) {
    unit.memory = state.memory;
    unit.edges = state.edges;
    unit.timers = state.timers;
    for (std::size_t i = 0; i < unit.sequences.size(); ++i)
        static_cast<engine::SequenceState&>(unit.sequences[i]) = state.sequences[i];
    unit.scan = state.scan;
}

} // namespace scan_replay

using scan_replay::ScanState;

// The scan state and the three ways to run a step: the machine code where
// there is some, else the fast interpreter, and the marking interpreter when
// conduction is wanted. Heap-allocated once, as the decoded code points into it.
struct UnitEngine::Tiers {
    Tiers(compiler::UnitImage image, const Bus& bus)
        : image(std::move(image)), operands(this->image.station, unit.memory, bus) {}

    compiler::UnitImage image;
    engine::UnitState unit;
    engine::OperandDecoder operands;
    engine::FastInterpreter fast;
    std::unique_ptr<engine::ScanMachineCode> machineCode; // or null: the fast interpreter
    std::vector<Conduction> conduction;
    std::vector<std::uint8_t> states; // ElementState bits, with the conduction
    // The bit outputs (=, S, R, T) by instruction, each with its variable as
    // the program reads it (a forced one's value, not the sink its writes go to).
    std::vector<std::pair<std::uint32_t, BitRef>> outputBits;
    ScanState scanStart;    // the state the last scan's steps started from
    bool replayDue = false; // conduction is not yet that of the last scan
    bool eagerConduction = false;
    std::vector<int> ranSteps; // steps run in the last scan, by index
    std::map<lang::Address, std::int64_t> forces;
    std::array<bool, 32> present{};
    std::array<bool, 32> cutOff{};
};

UnitEngine::UnitEngine(compiler::UnitImage image, const Bus& published)
    : m_tiers(std::make_unique<Tiers>(std::move(image), published)) {
    Tiers& t = *m_tiers;
    for (const auto& step : t.image.steps) {
        auto& sequence = t.unit.sequences[step.sequence];
        if (sequence.stepIndex.empty())
            sequence.stepIndex.assign(engine::kMaxStep + 1, -1);
        sequence.stepIndex[step.step] = static_cast<int>(t.unit.steps.size());
        t.unit.steps.push_back({step.sequence, step.step, step.first, step.count});
    }
    t.unit.edges.resize(t.image.edges);
    t.unit.timers.resize(t.image.timers);
    t.conduction.assign(t.image.code.size(), Conduction::NotRun);
    t.states.assign(t.image.code.size(), 0);
    for (std::size_t i = 0; i < t.image.code.size(); ++i) {
        const compiler::Op op = t.image.code[i].op;
        if (op == compiler::Op::Coil || op == compiler::Op::Set || op == compiler::Op::Reset ||
            op == compiler::Op::Toggle)
            t.outputBits.emplace_back(static_cast<std::uint32_t>(i),
                                      bitRef(t.unit.memory, t.image.code[i].operand, false));
    }
    t.present[t.image.station % 32] = true;
    decode();
    powerOn();
}

UnitEngine::~UnitEngine() = default;

const compiler::UnitImage& UnitEngine::image() const {
    return m_tiers->image;
}

UnitMemory& UnitEngine::memory() {
    return m_tiers->unit.memory;
}

const UnitMemory& UnitEngine::memory() const {
    return m_tiers->unit.memory;
}

bool UnitEngine::eagerConduction() const {
    return m_tiers->eagerConduction;
}

const Timer& UnitEngine::timer(std::size_t slot) const {
    return m_tiers->unit.timers[slot];
}

const std::map<lang::Address, std::int64_t>& UnitEngine::forces() const {
    return m_tiers->forces;
}

bool UnitEngine::hasSequence(int sequence) const {
    return sequence >= 0 && sequence < 10 && !m_tiers->unit.sequences[sequence].stepIndex.empty();
}

int UnitEngine::activeStep(int sequence) const {
    return hasSequence(sequence) ? m_tiers->unit.sequences[sequence].active : -1;
}

// At load and whenever forces change: operands are resolved again, and the
// faster tiers translate the result.
void UnitEngine::decode() {
    Tiers& t = *m_tiers;
    t.unit.code = t.operands.decode(t.image.code, t.forces);
    t.fast.translate(t.unit);
    t.machineCode.reset();
    t.machineCode = engine::lowerToMachineCode(t.unit);
}

void UnitEngine::powerOn(const std::vector<lang::Address>& keep) {
    Tiers& t = *m_tiers;
    std::vector<std::pair<lang::Address, std::int64_t>> kept;
    for (const auto& address : keep)
        kept.emplace_back(address, read(address));
    t.unit.memory = UnitMemory{};
    for (const auto& [address, value] : kept)
        write(address, value);
    t.unit.memory.systemRegisters[kSupplyVoltage] = 240; // 24.0 V until a scenario says otherwise
    for (auto& sequence : t.unit.sequences) {
        sequence.active = 0;
        sequence.stepNew = true;
        sequence.resetRequested = false;
    }
    std::fill(t.unit.edges.begin(), t.unit.edges.end(), engine::EdgeState{});
    std::fill(t.unit.timers.begin(), t.unit.timers.end(), Timer{});
    std::fill(t.conduction.begin(), t.conduction.end(), Conduction::NotRun);
    std::fill(t.states.begin(), t.states.end(), std::uint8_t{0});
    t.ranSteps.clear();
    t.replayDue = false;
    t.unit.scan = 0;
    applyForces();
}

void UnitEngine::setPresent(const std::array<bool, 32>& present) {
    m_tiers->present = present;
    m_tiers->present[m_tiers->image.station] = true;
}

void UnitEngine::setCutOff(const std::array<bool, 32>& cutOff) {
    m_tiers->cutOff = cutOff;
}

void UnitEngine::applyForces() {
    for (const auto& [address, value] : m_tiers->forces)
        write(address, value);
}

void UnitEngine::force(const lang::Address& address, std::int64_t value) {
    if (m_tiers->replayDue) // the last scan ran with the forces as they were
        replay();
    m_tiers->forces[address] = value;
    write(address, value);
    decode();
}

void UnitEngine::release(const lang::Address& address) {
    if (m_tiers->replayDue)
        replay();
    if (m_tiers->forces.erase(address))
        decode();
}

std::int64_t UnitEngine::read(const lang::Address& address) const {
    auto& memory = const_cast<UnitMemory&>(m_tiers->unit.memory);
    if (address.kind == AddressKind::Sequence)
        return activeStep(address.index);
    if (readsAsNumber(address.kind))
        return wordRef(memory, address).read();
    return bitRef(memory, address, false).read();
}

void UnitEngine::write(const lang::Address& address, std::int64_t value) {
    UnitMemory& memory = m_tiers->unit.memory;
    if (readsAsNumber(address.kind)) {
        WordRef ref = wordRef(memory, address);
        const bool narrow = ref.kind == WordRef::Kind::Register;
        ref.write(std::clamp<std::int64_t>(value, narrow ? -32768 : INT32_MIN,
                                           narrow ? 32767 : INT32_MAX));
        return;
    }
    // A scenario or the GUI sets an IQ's button, which the program reads,
    // not its lamp, which the program writes.
    bitRef(memory, address, address.kind != AddressKind::InputOutput).write(value != 0);
}

void UnitEngine::scan(std::int64_t timeMs, int cycleMs) {
    Tiers& t = *m_tiers;
    ++t.unit.scan;
    applyForces();
    auto& sm = t.unit.memory.systemMemories;
    sm[kSysInit] = t.unit.scan == 1;
    for (int memory : {kFlash, k1Hz, k10Hz, kFastFlash, kDoubleFlash})
        sm[memory] = flashing(memory, timeMs);
    for (int station = 0; station < 32; ++station)
        sm[static_cast<std::size_t>(100 + station)] = t.present[static_cast<std::size_t>(station)];
    t.operands.readBus(t.cutOff);
    if (t.eagerConduction) {
        runSteps(true, cycleMs);
        return;
    }
    save(t.unit, t.scanStart);
    t.scanStart.cycleMs = cycleMs;
    t.replayDue = true;
    runSteps(false, cycleMs);
}

void UnitEngine::runSteps(bool marking, int cycleMs) {
    Tiers& t = *m_tiers;
    engine::UnitState& unit = t.unit;
    unit.telegrams.clear();
    if (marking) {
        // Only the steps that ran last time have marks to clear.
        for (int index : t.ranSteps) {
            const engine::StepRun& step = unit.steps[static_cast<std::size_t>(index)];
            std::fill_n(t.conduction.begin() + step.first, step.count, Conduction::NotRun);
            std::fill_n(t.states.begin() + step.first, step.count, std::uint8_t{0});
        }
        t.ranSteps.clear();
    }
    auto& sm = unit.memory.systemMemories;
    for (int number = 0; number < 10; ++number) {
        engine::Sequence& sequence = unit.sequences[static_cast<std::size_t>(number)];
        if (sequence.stepIndex.empty())
            continue;
        const bool held = sequence.resetRequested;
        sequence.resetRequested = false;
        if (held && sequence.active != 0) {
            unit.leaveStep(sequence.stepIndex[sequence.active]);
            sequence.active = 0;
            sequence.stepNew = true;
        }
        int pendingJump = -1;
        sm[kStepNew] = sequence.stepNew;
        sequence.stepNew = false;
        const int stepIndex = sequence.stepIndex[static_cast<std::size_t>(sequence.active)];
        if (marking) {
            engine::runMarking(unit, stepIndex, pendingJump, cycleMs, t.conduction.data(),
                               t.states.data());
            t.ranSteps.push_back(stepIndex);
        } else if (t.machineCode) {
            engine::FastContext context = engine::startContext(unit, pendingJump, cycleMs);
            t.machineCode->entry(static_cast<std::size_t>(stepIndex))(&context);
        } else {
            t.fast.run(unit, stepIndex, pendingJump, cycleMs);
        }
        if (pendingJump >= 0 && !held) {
            unit.leaveStep(sequence.stepIndex[sequence.active]);
            sequence.active = pendingJump;
            sequence.stepNew = true;
        }
    }
    if (marking) // a bit output shows its variable as the scan left it
        for (const auto& [index, bit] : t.outputBits)
            if (t.conduction[index] != Conduction::NotRun)
                t.states[index] = bit.read() ? ElementState::Closed : 0;
}

// The engine is deterministic, so running the last scan's steps again from the
// state they started with, marking this time, gives exactly what they did.
// Other units' variables come from the decoder's copies, which only the next
// scan refreshes.
void UnitEngine::replay() {
    Tiers& t = *m_tiers;
    ScanState now;
    save(t.unit, now);
    restore(t.unit, t.scanStart);
    runSteps(true, t.scanStart.cycleMs);
    restore(t.unit, now);
    t.replayDue = false;
}

const std::vector<GatewayTelegram>& UnitEngine::telegrams() const {
    return m_tiers->unit.telegrams;
}

const std::vector<Conduction>& UnitEngine::conduction() const {
    if (m_tiers->replayDue) // engines are only ever created non-const (Simulation owns them)
        const_cast<UnitEngine*>(this)->replay();
    return m_tiers->conduction;
}

const std::vector<std::uint8_t>& UnitEngine::elementStates() const {
    conduction(); // marks both
    return m_tiers->states;
}

void UnitEngine::setEagerConduction(bool eager) {
    if (m_tiers->replayDue)
        replay();
    m_tiers->eagerConduction = eager;
}

} // namespace rs::sim
