#include "UnitEngine.h"

#include "lang/Ast.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstring>
#include <utility>

namespace rs::sim {

namespace {

using compiler::ArithOp;
using compiler::Op;
using lang::AddressKind;

constexpr int kStepNew = 0;
constexpr int kDitto = 1;
constexpr int kFlash = 2;
constexpr int k1Hz = 3;
constexpr int k10Hz = 4;
constexpr int kFastFlash = 5;
constexpr int kDoubleFlash = 6;
constexpr int kSysInit = 9;
constexpr int kTimerFreeze = 10;
constexpr int kOverflow = 11;
constexpr int kDivByZero = 12;
constexpr int kRemain = 2;
constexpr int kSupplyVoltage = 40;
constexpr int kMaxStep = 255;

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

// runStep's handlers: the image's ops, with the common cases split out so that
// their code has no branches on the data (a branch that depends on the data
// mispredicts whenever the data changes, and that is most of an interpreter's time).
enum Handler : std::uint8_t {
    HRung,
    HContactByte,
    HContact,
    HEdge,
    HTimer,
    HLoadA,
    HLoadB,
    HEqual,
    HGreater,
    HLess,
    HGreaterEqual,
    HLessEqual,
    HBranchOpen,
    HBranchNext,
    HBranchClose,
    HCoilByte,
    HCoil,
    HSetByte,
    HSet,
    HResetByte,
    HReset,
    HToggle,
    HJump,
    HSequenceReset,
    HArith,
    HandlerCount
};

// runFast's handlers.
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
    FEqual,
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
    FBitStatements, // a row of BitStatements
    FBitStatementsWithoutEdges,
    FWordStatements, // a row of WordStatements
    FEnd,
    FastHandlerCount
};

bool isWordKind(AddressKind kind) {
    switch (kind) {
    case AddressKind::Register:
    case AddressKind::DoubleRegister:
    case AddressKind::DoubleRegisterLow:
    case AddressKind::DoubleRegisterHigh:
    case AddressKind::SystemRegister:
        return true;
    default:
        return false;
    }
}

bool isDivision(ArithOp op) {
    return op == ArithOp::Div || op == ArithOp::DivAB;
}

// What an arithmetic output computes from the target's value and a and b,
// before saturation; divisions, with their remainder and division by zero,
// are the caller's.
std::int64_t undividedResult(ArithOp op, std::int64_t current, std::int64_t a, std::int64_t b) {
    switch (op) {
    case ArithOp::Increment:
        return current + 1;
    case ArithOp::Decrement:
        return current - 1;
    case ArithOp::Add:
        return current + a;
    case ArithOp::Sub:
        return current - a;
    case ArithOp::Mul:
        return current * a;
    case ArithOp::Copy:
        return a;
    case ArithOp::AddAB:
        return a + b;
    case ArithOp::SubAB:
        return a - b;
    case ArithOp::MulAB:
        return a * b;
    case ArithOp::Div:
    case ArithOp::DivAB:
        break;
    }
    return 0;
}

} // namespace

UnitEngine::UnitEngine(compiler::UnitImage image, const Bus& published)
    : m_image(std::move(image)), m_bus(published) {
    for (const auto& step : m_image.steps) {
        auto& sequence = m_sequences[step.sequence];
        if (sequence.stepIndex.empty())
            sequence.stepIndex.assign(kMaxStep + 1, -1);
        sequence.stepIndex[step.step] = static_cast<int>(m_steps.size());
        m_steps.push_back({step.sequence, step.step, step.first, step.count, 0});
    }
    m_edges.resize(m_image.edges);
    m_timers.resize(m_image.timers);
    m_conduction.assign(m_image.code.size(), Conduction::NotRun);
    m_present[m_image.station % 32] = true;
    decode();
    powerOn();
}

bool UnitEngine::hasSequence(int sequence) const {
    return sequence >= 0 && sequence < 10 && !m_sequences[sequence].stepIndex.empty();
}

int UnitEngine::activeStep(int sequence) const {
    return hasSequence(sequence) ? m_sequences[sequence].active : -1;
}

namespace {

// The bytes behind a reference, for copying another unit's variable.
std::size_t sizeOf(const BitRef& ref) {
    switch (ref.kind) {
    case BitRef::Kind::Byte:
        return 1;
    case BitRef::Kind::RegisterBit:
        return 2;
    case BitRef::Kind::Analog:
        return 4;
    case BitRef::Kind::None:
        break;
    }
    return 0;
}

std::size_t sizeOf(const WordRef& ref) {
    switch (ref.kind) {
    case WordRef::Kind::Register:
        return 2;
    case WordRef::Kind::Double:
    case WordRef::Kind::Wide:
        return 4;
    case WordRef::Kind::None:
        break;
    }
    return 0;
}

const void* placeOf(const BitRef& ref) {
    return ref.kind == BitRef::Kind::Byte          ? static_cast<const void*>(ref.byte)
           : ref.kind == BitRef::Kind::RegisterBit ? static_cast<const void*>(ref.word)
                                                   : static_cast<const void*>(ref.wide);
}

const void* placeOf(const WordRef& ref) {
    return ref.kind == WordRef::Kind::Wide ? static_cast<const void*>(ref.wide)
                                           : static_cast<const void*>(ref.word);
}

} // namespace

UnitMemory& UnitEngine::remoteCopy(int station) {
    auto& copy = m_remote[static_cast<std::size_t>(station) % 32];
    if (!copy)
        copy = std::make_unique<UnitMemory>();
    return *copy;
}

template <typename Ref>
Ref UnitEngine::readRemote(const lang::Address& address,
                           Ref (*locate)(UnitMemory&, const lang::Address&)) {
    const auto station = static_cast<std::size_t>(address.unit) % 32;
    UnitMemory& copy = remoteCopy(address.unit);
    const Ref ref = locate(copy, address);
    if (const std::size_t size = sizeOf(ref)) {
        const auto offset = static_cast<const std::uint8_t*>(placeOf(ref)) -
                            reinterpret_cast<const std::uint8_t*>(&copy);
        m_remoteCopies.push_back({reinterpret_cast<std::uint8_t*>(&copy) + offset,
                                  reinterpret_cast<const std::uint8_t*>(&m_bus[station]) + offset,
                                  size});
    }
    return ref;
}

BitRef UnitEngine::decodeBit(const lang::Address& address, bool forWriting) {
    if (address.unit != m_image.station) // the compiler lets a unit only read others' variables
        return readRemote<BitRef>(address, [](UnitMemory& memory, const lang::Address& a) {
            return bitRef(memory, a, false);
        });
    if (forWriting && m_forces.count(address))
        return bitRef(m_sink, address, true);
    return bitRef(m_memory, address, forWriting);
}

WordRef UnitEngine::decodeWord(const lang::Address& address) {
    if (address.unit != m_image.station)
        return readRemote<WordRef>(address, wordRef);
    return wordRef(m_memory, address);
}

void UnitEngine::Decoded::pointAt(const BitRef& target) {
    refKind = static_cast<std::uint8_t>(target.kind);
    bit = static_cast<std::uint8_t>(target.bit);
    ref = target.kind == BitRef::Kind::Byte          ? static_cast<void*>(target.byte)
          : target.kind == BitRef::Kind::RegisterBit ? static_cast<void*>(target.word)
                                                     : static_cast<void*>(target.wide);
}

void UnitEngine::Decoded::pointAt(const WordRef& target) {
    refKind = static_cast<std::uint8_t>(target.kind);
    ref = target.kind == WordRef::Kind::Wide ? static_cast<void*>(target.wide)
                                             : static_cast<void*>(target.word);
}

bool UnitEngine::Decoded::readBit() const {
    switch (static_cast<BitRef::Kind>(refKind)) {
    case BitRef::Kind::Byte:
        return *static_cast<const std::uint8_t*>(ref) != 0;
    case BitRef::Kind::RegisterBit:
        return (static_cast<std::uint16_t>(*static_cast<const std::int16_t*>(ref)) >> bit) & 1u;
    case BitRef::Kind::Analog:
        return *static_cast<const std::int32_t*>(ref) != 0;
    case BitRef::Kind::None:
        break;
    }
    return false;
}

void UnitEngine::Decoded::writeBit(bool value) const {
    BitRef target;
    target.kind = static_cast<BitRef::Kind>(refKind);
    target.byte = static_cast<std::uint8_t*>(ref);
    target.word = static_cast<std::int16_t*>(ref);
    target.wide = static_cast<std::int32_t*>(ref);
    target.bit = bit;
    target.write(value);
}

std::int64_t UnitEngine::Decoded::readWord() const {
    WordRef source;
    source.kind = static_cast<WordRef::Kind>(refKind);
    source.word = static_cast<std::int16_t*>(ref);
    source.wide = static_cast<std::int32_t*>(ref);
    return source.read();
}

void UnitEngine::Decoded::writeWord(std::int64_t value) const {
    WordRef target;
    target.kind = static_cast<WordRef::Kind>(refKind);
    target.word = static_cast<std::int16_t*>(ref);
    target.wide = static_cast<std::int32_t*>(ref);
    target.write(value);
}

bool UnitEngine::Decoded::wideWord() const {
    return static_cast<WordRef::Kind>(refKind) != WordRef::Kind::Register;
}

std::uint8_t UnitEngine::handlerFor(const Decoded& d) {
    const bool byte = d.refKind == static_cast<std::uint8_t>(BitRef::Kind::Byte);
    switch (d.op) {
    case Op::Rung:
        return HRung;
    case Op::Contact:
        return byte ? HContactByte : HContact;
    case Op::Edge:
        return HEdge;
    case Op::Timer:
        return HTimer;
    case Op::LoadA:
        return HLoadA;
    case Op::LoadB:
        return HLoadB;
    case Op::Compare:
        return static_cast<std::uint8_t>(HEqual + d.aux);
    case Op::BranchOpen:
        return HBranchOpen;
    case Op::BranchNext:
        return HBranchNext;
    case Op::BranchClose:
        return HBranchClose;
    case Op::Coil:
        return byte ? HCoilByte : HCoil;
    case Op::Set:
        return byte ? HSetByte : HSet;
    case Op::Reset:
        return byte ? HResetByte : HReset;
    case Op::Toggle:
        return HToggle;
    case Op::Jump:
        return HJump;
    case Op::SequenceReset:
        return HSequenceReset;
    case Op::Arith:
        return HArith;
    }
    return HRung;
}

void UnitEngine::decode() {
    m_remoteCopies.clear();
    m_code.clear();
    m_code.reserve(m_image.code.size());
    for (const auto& in : m_image.code) {
        Decoded d{in.op, 0, in.flags, in.aux, 0, 0, false, in.slot, in.constant, nullptr};
        switch (in.op) {
        case Op::Contact:
        case Op::Edge:
            d.pointAt(decodeBit(in.operand, false));
            break;
        case Op::Coil:
        case Op::Set:
        case Op::Reset:
        case Op::Toggle:
            d.pointAt(decodeBit(in.operand, true));
            break;
        case Op::LoadA:
        case Op::LoadB:
        case Op::Timer:
            if (!(in.flags & compiler::ConstantOperand))
                d.pointAt(decodeWord(in.operand));
            break;
        case Op::Arith:
            d.pointAt(decodeWord(in.operand));
            d.dropWrite = m_forces.count(in.operand) != 0;
            break;
        default:
            break;
        }
        d.handler = handlerFor(d);
        m_code.push_back(d);
    }
    std::sort(m_remoteCopies.begin(), m_remoteCopies.end(),
              [](const RemoteCopy& x, const RemoteCopy& y) { return x.to < y.to; });
    m_remoteCopies.erase(std::unique(m_remoteCopies.begin(), m_remoteCopies.end(),
                                     [](const RemoteCopy& x, const RemoteCopy& y) {
                                         return x.to == y.to && x.size == y.size;
                                     }),
                         m_remoteCopies.end());
    translate();
    compileSteps();
}

void UnitEngine::powerOn(const std::vector<lang::Address>& keep) {
    std::vector<std::pair<lang::Address, std::int64_t>> kept;
    for (const auto& address : keep)
        kept.emplace_back(address, read(address));
    m_memory = UnitMemory{};
    for (const auto& [address, value] : kept)
        write(address, value);
    m_memory.systemRegisters[kSupplyVoltage] = 240; // 24.0 V until a scenario says otherwise
    for (auto& sequence : m_sequences) {
        sequence.active = 0;
        sequence.stepNew = true;
        sequence.resetRequested = false;
    }
    std::fill(m_edges.begin(), m_edges.end(), EdgeState{});
    std::fill(m_timers.begin(), m_timers.end(), Timer{});
    std::fill(m_conduction.begin(), m_conduction.end(), Conduction::NotRun);
    m_ranSteps.clear();
    m_replayDue = false;
    m_scan = 0;
    applyForces();
}

void UnitEngine::setPresent(const std::array<bool, 32>& present) {
    m_present = present;
    m_present[m_image.station] = true;
}

void UnitEngine::applyForces() {
    for (const auto& [address, value] : m_forces)
        write(address, value);
}

void UnitEngine::force(const lang::Address& address, std::int64_t value) {
    if (m_replayDue) // the last scan ran with the forces as they were
        replay();
    m_forces[address] = value;
    write(address, value);
    decode();
}

void UnitEngine::release(const lang::Address& address) {
    if (m_replayDue)
        replay();
    if (m_forces.erase(address))
        decode();
}

std::int64_t UnitEngine::read(const lang::Address& address) const {
    auto& memory = const_cast<UnitMemory&>(m_memory);
    if (address.kind == AddressKind::Sequence)
        return activeStep(address.index);
    if (isWordKind(address.kind))
        return wordRef(memory, address).read();
    if (address.kind == AddressKind::AnalogInput)
        return wordRef(memory, address).read();
    return bitRef(memory, address, false).read();
}

void UnitEngine::write(const lang::Address& address, std::int64_t value) {
    if (isWordKind(address.kind) || address.kind == AddressKind::AnalogInput) {
        WordRef ref = wordRef(m_memory, address);
        const bool narrow = ref.kind == WordRef::Kind::Register;
        ref.write(std::clamp<std::int64_t>(value, narrow ? -32768 : INT32_MIN,
                                           narrow ? 32767 : INT32_MAX));
        return;
    }
    bitRef(m_memory, address, true).write(value != 0);
}

void UnitEngine::scan(std::int64_t timeMs, int cycleMs) {
    ++m_scan;
    applyForces();
    auto& sm = m_memory.systemMemories;
    sm[kSysInit] = m_scan == 1;
    for (int memory : {kFlash, k1Hz, k10Hz, kFastFlash, kDoubleFlash})
        sm[memory] = flashing(memory, timeMs);
    for (int station = 0; station < 32; ++station)
        sm[static_cast<std::size_t>(100 + station)] = m_present[static_cast<std::size_t>(station)];
    for (const RemoteCopy& copy : m_remoteCopies)
        std::memcpy(copy.to, copy.from, copy.size);
    if (m_eagerConduction) {
        runSteps(true, cycleMs);
        return;
    }
    save(m_scanStart);
    m_scanStart.cycleMs = cycleMs;
    m_replayDue = true;
    runSteps(false, cycleMs);
}

void UnitEngine::runSteps(bool marking, int cycleMs) {
    if (marking) {
        // Only the steps that ran last time have marks to clear.
        for (int index : m_ranSteps) {
            const StepRun& step = m_steps[static_cast<std::size_t>(index)];
            std::fill_n(m_conduction.begin() + step.first, step.count, Conduction::NotRun);
        }
        m_ranSteps.clear();
    }
    auto& sm = m_memory.systemMemories;
    for (int number = 0; number < 10; ++number) {
        Sequence& sequence = m_sequences[static_cast<std::size_t>(number)];
        if (sequence.stepIndex.empty())
            continue;
        const bool held = sequence.resetRequested;
        sequence.resetRequested = false;
        if (held && sequence.active != 0) {
            leaveStep(sequence.stepIndex[sequence.active]);
            sequence.active = 0;
            sequence.stepNew = true;
        }
        int pendingJump = -1;
        sm[kStepNew] = sequence.stepNew;
        sequence.stepNew = false;
        const int stepIndex = sequence.stepIndex[static_cast<std::size_t>(sequence.active)];
        if (marking) {
            runStep(stepIndex, pendingJump, cycleMs);
            m_ranSteps.push_back(stepIndex);
        } else if (m_machineCode) {
            FastContext context; // the branches are written before they are read
            context.engine = this;
            context.pendingJump = &pendingJump;
            context.cycleMs = cycleMs;
            context.depth = 0;
            context.a = 0;
            context.b = 0;
            m_machineCode->entry(static_cast<std::size_t>(stepIndex))(&context);
        } else {
            runFast(m_fast.data() + m_steps[static_cast<std::size_t>(stepIndex)].fastFirst,
                    pendingJump, cycleMs);
        }
        if (pendingJump >= 0 && !held) {
            leaveStep(sequence.stepIndex[sequence.active]);
            sequence.active = pendingJump;
            sequence.stepNew = true;
        }
    }
}

void UnitEngine::save(ScanState& state) const {
    state.memory = m_memory;
    state.edges = m_edges;
    state.timers = m_timers;
    for (std::size_t i = 0; i < m_sequences.size(); ++i)
        state.sequences[i] = m_sequences[i];
    state.scan = m_scan;
}

void UnitEngine::restore(const ScanState& state) {
    m_memory = state.memory;
    m_edges = state.edges;
    m_timers = state.timers;
    for (std::size_t i = 0; i < m_sequences.size(); ++i)
        static_cast<SequenceState&>(m_sequences[i]) = state.sequences[i];
    m_scan = state.scan;
}

// The engine is deterministic, so running the last scan's steps again from the
// state they started with, marking this time, gives exactly what they did.
// Other units' variables come from m_remote, which only the next scan refreshes.
void UnitEngine::replay() {
    ScanState now;
    save(now);
    restore(m_scanStart);
    runSteps(true, m_scanStart.cycleMs);
    restore(now);
    m_replayDue = false;
}

const std::vector<Conduction>& UnitEngine::conduction() const {
    if (m_replayDue) // engines are only ever created non-const (Simulation owns them)
        const_cast<UnitEngine*>(this)->replay();
    return m_conduction;
}

void UnitEngine::setEagerConduction(bool eager) {
    if (m_replayDue)
        replay();
    m_eagerConduction = eager;
}

void UnitEngine::leaveStep(int index) {
    const StepRun& step = m_steps[static_cast<std::size_t>(index)];
    for (std::uint32_t i = step.first; i < step.first + step.count; ++i)
        if (m_code[i].op == Op::Coil)
            m_code[i].writeBit(false);
}

// The power an edge occurrence passes: whether it sees its edge, negated if asked.
unsigned UnitEngine::edge(const Decoded& in) {
    EdgeState& state = m_edges[in.slot];
    const bool value = in.readBit() != bool(in.flags & compiler::OperandNegated);
    bool seen = false;
    if (state.seen)
        seen = (in.flags & compiler::Rising) ? (value && !state.last) : (!value && state.last);
    state.seen = true;
    state.last = value;
    return static_cast<unsigned>(seen) ^ (in.flags & compiler::Negated);
}

// edge() for a byte operand, without branches on the data.
unsigned UnitEngine::byteEdge(const ByteEdge& e) {
    const unsigned value = static_cast<unsigned>(*e.operand != 0) ^ e.operandNegated;
    const unsigned last = e.state->last;
    // Rising: the value is 1 and was 0; falling: it was 1 and is 0.
    const unsigned toward = e.rising ? value : last;
    const unsigned seen = e.state->seen & (value ^ last) & toward;
    e.state->seen = true;
    e.state->last = value != 0;
    return seen ^ e.negated;
}

// Threaded dispatch (GCC's labels as values): each handler jumps straight to
// the next one, so the processor predicts each transition on its own. On a
// 32-unit project that is what keeps the engine near compiled code.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
void UnitEngine::runStep(int index, int& pendingJump, int cycleMs) {
    const StepRun& step = m_steps[static_cast<std::size_t>(index)];
    if (step.count == 0)
        return;
    auto& sm = m_memory.systemMemories;
    struct Branch {
        unsigned in;
        unsigned any;
    };
    Branch branches[64];
    int depth = 0;
    unsigned power = 1; // 0 or 1, combined with & and | so that nothing branches on it
    std::int64_t a = 0;
    std::int64_t b = 0;
    const Decoded* in = m_code.data() + step.first;
    const Decoded* const end = in + step.count;
    Conduction* mark = m_conduction.data() + step.first;
    static_assert(compiler::Negated == 1);

    static const void* const handlers[] = {
        &&rung,         &&contactByte, &&contact,    &&edge,          &&timer,
        &&loadA,        &&loadB,       &&equal,      &&greater,       &&less,
        &&greaterEqual, &&lessEqual,   &&branchOpen, &&branchNext,    &&branchClose,
        &&coilByte,     &&coil,        &&setByte,    &&set,           &&resetByte,
        &&reset,        &&toggle,      &&jump,       &&sequenceReset, &&arith};
    static_assert(std::size(handlers) == HandlerCount);
#define RS_NEXT()                                                                                  \
    do {                                                                                           \
        *mark++ = static_cast<Conduction>(1 + power);                                              \
        if (++in == end)                                                                           \
            return;                                                                                \
        goto* handlers[in->handler];                                                               \
    } while (false)
#define RS_NEGATED (in->flags & compiler::Negated)
#define RS_BYTE (*static_cast<std::uint8_t*>(in->ref))

    goto* handlers[in->handler];
rung:
    power = 1;
    RS_NEXT();
contactByte:
    power &= static_cast<unsigned>(RS_BYTE != 0) ^ RS_NEGATED;
    RS_NEXT();
contact:
    power &= static_cast<unsigned>(in->readBit()) ^ RS_NEGATED;
    RS_NEXT();
edge:
    power &= edge(*in);
    RS_NEXT();
timer:
    power = timer(*in, power != 0, cycleMs);
    RS_NEXT();
loadA:
    a = (in->flags & compiler::ConstantOperand) ? in->constant : in->readWord();
    RS_NEXT();
loadB:
    b = (in->flags & compiler::ConstantOperand) ? in->constant : in->readWord();
    RS_NEXT();
equal:
    power &= static_cast<unsigned>(a == b) ^ RS_NEGATED;
    RS_NEXT();
greater:
    power &= static_cast<unsigned>(a > b) ^ RS_NEGATED;
    RS_NEXT();
less:
    power &= static_cast<unsigned>(a < b) ^ RS_NEGATED;
    RS_NEXT();
greaterEqual:
    power &= static_cast<unsigned>(a >= b) ^ RS_NEGATED;
    RS_NEXT();
lessEqual:
    power &= static_cast<unsigned>(a <= b) ^ RS_NEGATED;
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
    RS_BYTE = static_cast<std::uint8_t>(power);
    sm[kDitto] = static_cast<std::uint8_t>(power);
    RS_NEXT();
coil:
    in->writeBit(power != 0);
    sm[kDitto] = static_cast<std::uint8_t>(power);
    RS_NEXT();
setByte:
    RS_BYTE = static_cast<std::uint8_t>(RS_BYTE | power);
    sm[kDitto] = static_cast<std::uint8_t>(power);
    RS_NEXT();
set:
    if (power)
        in->writeBit(true);
    sm[kDitto] = static_cast<std::uint8_t>(power);
    RS_NEXT();
resetByte:
    RS_BYTE = static_cast<std::uint8_t>(RS_BYTE & (power ^ 1u));
    sm[kDitto] = static_cast<std::uint8_t>(power);
    RS_NEXT();
reset:
    if (power)
        in->writeBit(false);
    sm[kDitto] = static_cast<std::uint8_t>(power);
    RS_NEXT();
toggle:
    if (power)
        in->writeBit(!in->readBit());
    sm[kDitto] = static_cast<std::uint8_t>(power);
    RS_NEXT();
jump:
    if (power)
        pendingJump = in->slot; // the last jump taken in the step wins
    RS_NEXT();
sequenceReset:
    if (power && in->slot < 10)
        m_sequences[in->slot].resetRequested = true;
    RS_NEXT();
arith:
    if (power)
        arithmetic(*in, a, b);
    RS_NEXT();
#undef RS_BYTE
#undef RS_NEGATED
#undef RS_NEXT
}
#pragma GCC diagnostic pop

void UnitEngine::translate() {
    const void* const* table = nullptr;
    int unused = 0;
    runFast(nullptr, unused, 0, &table);
    m_fast.clear();
    m_byteEdges.clear();
    // runFast points into m_byteEdges: it must not grow once filled.
    m_byteEdges.reserve(static_cast<std::size_t>(std::count_if(
        m_code.begin(), m_code.end(), [](const Decoded& d) { return d.handler == HEdge; })));
    const std::size_t rungs = static_cast<std::size_t>(std::count_if(
        m_code.begin(), m_code.end(), [](const Decoded& d) { return d.handler == HRung; }));
    m_bitStatements.clear();
    m_bitStatements.reserve(rungs);
    m_bitStatementRows.clear();
    m_bitStatementRows.reserve(rungs);
    m_wordStatements.clear();
    m_wordStatements.reserve(rungs);
    m_wordStatementRows.clear();
    m_wordStatementRows.reserve(rungs);
    std::vector<FastHandler> kinds; // of m_fast's entries
    for (StepRun& step : m_steps) {
        step.fastFirst = static_cast<std::uint32_t>(m_fast.size());
        const std::size_t begin = m_fast.size();
        const auto last = [&] {
            return m_fast.size() > begin ? kinds.back() : FEnd;
        };
        const auto replaceLast = [&](FastHandler kind) {
            kinds.back() = kind;
            m_fast.back().handler = table[kind];
        };
        for (std::uint32_t i = step.first; i < step.first + step.count; ++i) {
            Decoded& d = m_code[i];
            const bool negated = d.flags & compiler::Negated;
            void* arg = &d;
            FastHandler kind = FEnd;
            if (d.handler == HRung) {
                std::uint32_t end = i + 1;
                while (end < step.first + step.count && m_code[end].handler != HRung)
                    ++end;
                BitStatement statement{};
                if (toBitStatement(i, end, statement)) {
                    m_bitStatements.push_back(statement);
                    if (last() == FBitStatements) {
                        m_bitStatementRows.back().end = &m_bitStatements.back() + 1;
                    } else {
                        m_bitStatementRows.push_back(
                            {&m_bitStatements.back(), &m_bitStatements.back() + 1});
                        m_fast.push_back({table[FBitStatements], &m_bitStatementRows.back()});
                        kinds.push_back(FBitStatements);
                    }
                    i = end - 1;
                    continue;
                }
                WordStatement word{};
                if (toWordStatement(i, end, word)) {
                    m_wordStatements.push_back(word);
                    if (last() == FWordStatements) {
                        m_wordStatementRows.back().end = &m_wordStatements.back() + 1;
                    } else {
                        m_wordStatementRows.push_back(
                            {&m_wordStatements.back(), &m_wordStatements.back() + 1});
                        m_fast.push_back({table[FWordStatements], &m_wordStatementRows.back()});
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
                    m_fast.pop_back();
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
                        {static_cast<const std::uint8_t*>(d.ref), &m_edges[d.slot],
                         static_cast<std::uint8_t>((d.flags & compiler::OperandNegated) != 0),
                         static_cast<std::uint8_t>((d.flags & compiler::Rising) != 0),
                         static_cast<std::uint8_t>(negated)});
                    arg = &m_byteEdges.back();
                }
                kind = byte ? FByteEdge : FEdge;
                if (last() == FRung) {
                    m_fast.pop_back();
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
            case HandlerCount:
                break;
            }
            m_fast.push_back({table[kind], arg});
            kinds.push_back(kind);
        }
        m_fast.push_back({table[FEnd], nullptr});
        kinds.push_back(FEnd);
    }
    for (std::size_t i = 0; i < m_fast.size(); ++i) {
        if (kinds[i] != FBitStatements)
            continue;
        const auto& row = *static_cast<const Row<BitStatement>*>(m_fast[i].arg);
        if (std::all_of(row.first, row.end,
                        [this](const BitStatement& st) { return st.edge == &m_noEdge; }))
            m_fast[i].handler = table[FBitStatementsWithoutEdges];
    }
}

bool UnitEngine::toBitStatement(std::uint32_t first, std::uint32_t end, BitStatement& out) {
    static const std::uint8_t one = 1;
    static const std::uint8_t zero = 0;
    static std::uint8_t nowhere = 0; // the target of a jump
    if (end - first < 2)
        return false;
    // The byte and mask of a bit operand (a register's bits are bytes in
    // memory order, so this needs a little-endian machine).
    const auto locate = [](const Decoded& d, const std::uint8_t*& byte, std::uint8_t& mask) {
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
        const Decoded& d = m_code[i];
        const auto negated = static_cast<std::uint8_t>(d.flags & compiler::Negated);
        if (d.op == Op::Contact && contacts < 2) {
            if (!locate(d, out.read[contacts], out.mask[contacts]))
                return false;
            out.negated[contacts++] = negated;
        } else if (d.op == Op::Edge && !edge) {
            if (!locate(d, out.read[2], out.mask[2]))
                return false;
            edge = true;
            out.edge = &m_edges[d.slot];
            out.negated[2] = (d.flags & compiler::OperandNegated) != 0;
            out.edgeRising = (d.flags & compiler::Rising) != 0;
            out.edgeNegated = negated;
        } else {
            return false;
        }
    }
    const Decoded& output = m_code[end - 1];
    out.keepOff = 0xFF;
    if (output.op == Op::Jump) {
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
        out.flipOn = 1;
        out.keepOff = static_cast<std::uint8_t>(~out.targetMask);
        return true;
    case Op::Set:
        out.flipOn = 1;
        return true;
    case Op::Reset:
        return true;
    case Op::Toggle:
        out.keepOn = 1;
        out.flipOn = 1;
        return true;
    default:
        return false;
    }
}

bool UnitEngine::toWordStatement(std::uint32_t first, std::uint32_t end, WordStatement& out) {
    static const std::uint8_t one = 1;
    static const std::uint8_t zero = 0;
    static const std::int32_t nothing = 0;
    if (end - first < 2 || std::endian::native != std::endian::little)
        return false;
    const Decoded& output = m_code[end - 1];
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
        const Decoded& d = m_code[i];
        const bool byte = d.refKind == static_cast<std::uint8_t>(BitRef::Kind::Byte);
        const bool series = loads == 0;
        if (d.op == Op::Contact && !contact && byte && series) {
            contact = true;
            out.read[0] = static_cast<const std::uint8_t*>(d.ref);
            out.negated[0] = d.flags & compiler::Negated;
        } else if (d.op == Op::Edge && !edge && byte && series) {
            edge = true;
            out.read[1] = static_cast<const std::uint8_t*>(d.ref);
            out.edge = &m_edges[d.slot];
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
    switch (op) {
    case ArithOp::Increment:
        out.fromCurrent = 1;
        out.yConstant = 1;
        break;
    case ArithOp::Decrement:
        out.fromCurrent = 1;
        out.yConstant = -1;
        break;
    case ArithOp::Add:
        out.fromCurrent = 1;
        out.yA = 1;
        break;
    case ArithOp::Sub:
        out.fromCurrent = 1;
        out.yA = -1;
        break;
    case ArithOp::Mul:
        out.fromCurrent = 1;
        out.yA = 1;
        out.multiply = 1;
        break;
    case ArithOp::Copy:
        out.fromA = 1;
        break;
    case ArithOp::AddAB:
        out.fromA = 1;
        out.yB = 1;
        break;
    case ArithOp::SubAB:
        out.fromA = 1;
        out.yB = -1;
        break;
    case ArithOp::MulAB:
        out.fromA = 1;
        out.yB = 1;
        out.multiply = 1;
        break;
    case ArithOp::Div:
    case ArithOp::DivAB:
        return false;
    }
    return true;
}

void UnitEngine::runWordStatements(const Row<WordStatement>& row, std::int64_t& a,
                                   std::int64_t& b) {
    auto& sm = m_memory.systemMemories;
    for (const WordStatement* st = row.first; st != row.end; ++st) {
        const unsigned value =
            static_cast<unsigned>((*st->read[1] & st->mask[1]) != 0) ^ st->negated[1];
        const unsigned last = st->edge->last;
        const unsigned seen = st->edge->seen & (value ^ last) & (st->edgeRising ? value : last);
        st->edge->seen = true;
        st->edge->last = value != 0;
        const unsigned on =
            ((static_cast<unsigned>((*st->read[0] & st->mask[0]) != 0) ^ st->negated[0]) &
             (seen ^ st->edgeNegated));
        const auto load = [st](int i) {
            std::uint32_t raw = 0;
            std::memcpy(&raw, st->load[i], sizeof raw);
            return static_cast<std::int64_t>(static_cast<std::int32_t>(raw << st->narrow[i]) >>
                                             st->narrow[i]);
        };
        const std::int64_t loadedA = load(0);
        const std::int64_t loadedB = load(1);
        a = st->loads[0] ? loadedA : a;
        b = st->loads[1] ? loadedB : b;
        const std::int64_t current = *st->target;
        const std::int64_t x = current * st->fromCurrent + a * st->fromA;
        const std::int64_t y = st->yConstant + a * st->yA + b * st->yB;
        const std::int64_t result = st->multiply ? x * y : x + y;
        const bool overflow = result < -32768 || result > 32767;
        const auto saturated =
            static_cast<std::int16_t>(std::clamp<std::int64_t>(result, -32768, 32767));
        *st->target = on ? saturated : static_cast<std::int16_t>(current);
        sm[kOverflow] = on ? overflow : sm[kOverflow];
    }
}

template <bool withEdges>
inline void UnitEngine::runBitStatements(const Row<BitStatement>& row, std::uint8_t& ditto,
                                         int& pendingJump) {
    int jump = pendingJump;
    for (const BitStatement* st = row.first; st != row.end; ++st) {
        const auto bit = [st](int i) {
            return static_cast<unsigned>((*st->read[i] & st->mask[i]) != 0) ^ st->negated[i];
        };
        unsigned on = bit(0) & bit(1);
        if constexpr (withEdges) {
            const unsigned value = bit(2);
            const unsigned last = st->edge->last;
            const unsigned seen = st->edge->seen & (value ^ last) & (st->edgeRising ? value : last);
            st->edge->seen = true;
            st->edge->last = value != 0;
            on &= seen ^ st->edgeNegated;
        }
        const unsigned old = *st->target;
        const unsigned output =
            (static_cast<unsigned>((old & st->targetMask) != 0) & st->keepOn) ^ st->flipOn;
        const unsigned withPower = (old & ~st->targetMask) | (st->targetOne & (0u - output));
        const unsigned without = old & st->keepOff;
        const unsigned select = 0u - on;
        *st->target = static_cast<std::uint8_t>((withPower & select) | (without & ~select));
        jump = (on & st->jump) ? st->jumpStep : jump;
        const unsigned keep = 0u - static_cast<unsigned>(st->jump); // a jump leaves SM_Ditto
        // Stored each time: the next statement may read it.
        ditto = static_cast<std::uint8_t>((ditto & keep) | (on & ~keep));
    }
    pendingJump = jump;
}

// runFast's handlers, one function each so that the machine code can call
// them: what the power becomes, from the power before and the argument (the
// operand's address or the Decoded entry, by handler).
#define RS_FAST_OP(kind)                                                                           \
    template <>                                                                                    \
    [[gnu::always_inline]] inline unsigned UnitEngine::fastOp<kind>(                               \
        [[maybe_unused]] FastContext & c, [[maybe_unused]] const void* arg,                        \
        [[maybe_unused]] unsigned power)
#define RS_IN (*static_cast<const Decoded*>(arg))
#define RS_BYTE (*static_cast<std::uint8_t*>(const_cast<void*>(arg)))
#define RS_NEGATED static_cast<unsigned>(RS_IN.flags & compiler::Negated)
#define RS_DITTO (c.engine->m_memory.systemMemories[kDitto])

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
    return power & c.engine->edge(RS_IN);
}
RS_FAST_OP(FEdgeStart) {
    return c.engine->edge(RS_IN);
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
    return c.engine->timer(RS_IN, power != 0, c.cycleMs);
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
    return power & (static_cast<unsigned>(c.a == c.b) ^ RS_NEGATED);
}
RS_FAST_OP(FGreater) {
    return power & (static_cast<unsigned>(c.a > c.b) ^ RS_NEGATED);
}
RS_FAST_OP(FLess) {
    return power & (static_cast<unsigned>(c.a < c.b) ^ RS_NEGATED);
}
RS_FAST_OP(FGreaterEqual) {
    return power & (static_cast<unsigned>(c.a >= c.b) ^ RS_NEGATED);
}
RS_FAST_OP(FLessEqual) {
    return power & (static_cast<unsigned>(c.a <= c.b) ^ RS_NEGATED);
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
    RS_BYTE = static_cast<std::uint8_t>(power);
    RS_DITTO = static_cast<std::uint8_t>(power);
    return power;
}
RS_FAST_OP(FCoilByteRung) {
    fastOp<FCoilByte>(c, arg, power);
    return 1;
}
RS_FAST_OP(FCoil) {
    RS_IN.writeBit(power != 0);
    RS_DITTO = static_cast<std::uint8_t>(power);
    return power;
}
RS_FAST_OP(FCoilRegisterBit) {
    auto& word = *static_cast<std::uint16_t*>(RS_IN.ref);
    const auto mask = static_cast<unsigned>(1u << RS_IN.bit);
    word = static_cast<std::uint16_t>((word & ~mask) | (power * mask));
    RS_DITTO = static_cast<std::uint8_t>(power);
    return power;
}
RS_FAST_OP(FSetByte) {
    RS_BYTE = static_cast<std::uint8_t>(RS_BYTE | power);
    RS_DITTO = static_cast<std::uint8_t>(power);
    return power;
}
RS_FAST_OP(FSetByteRung) {
    fastOp<FSetByte>(c, arg, power);
    return 1;
}
RS_FAST_OP(FSet) {
    if (power)
        RS_IN.writeBit(true);
    RS_DITTO = static_cast<std::uint8_t>(power);
    return power;
}
RS_FAST_OP(FResetByte) {
    RS_BYTE = static_cast<std::uint8_t>(RS_BYTE & (power ^ 1u));
    RS_DITTO = static_cast<std::uint8_t>(power);
    return power;
}
RS_FAST_OP(FResetByteRung) {
    fastOp<FResetByte>(c, arg, power);
    return 1;
}
RS_FAST_OP(FReset) {
    if (power)
        RS_IN.writeBit(false);
    RS_DITTO = static_cast<std::uint8_t>(power);
    return power;
}
RS_FAST_OP(FToggle) {
    if (power)
        RS_IN.writeBit(!RS_IN.readBit());
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
        c.engine->m_sequences[RS_IN.slot].resetRequested = true;
    return power;
}
RS_FAST_OP(FArith) {
    if (power)
        c.engine->arithmetic(RS_IN, c.a, c.b);
    return power;
}
RS_FAST_OP(FArithRegister) {
    if (!power)
        return power;
    auto& target = *static_cast<std::int16_t*>(RS_IN.ref);
    const std::int64_t current = target;
    // translate() leaves divisions to arithmetic().
    const std::int64_t result = undividedResult(static_cast<ArithOp>(RS_IN.aux), current, c.a, c.b);
    c.engine->m_memory.systemMemories[kOverflow] = result < -32768 || result > 32767;
    target = static_cast<std::int16_t>(std::clamp<std::int64_t>(result, -32768, 32767));
    return power;
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
    c.engine->runWordStatements(*static_cast<const Row<WordStatement>*>(arg), c.a, c.b);
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

template <int kind> unsigned UnitEngine::fastCall(void* context, const void* arg, unsigned power) {
    return fastOp<kind>(*static_cast<FastContext*>(context), arg, power);
}

// The same instructions as runStep without the marks, in the form translate()
// made: a scan that nobody looks at in detail costs what its logic costs.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
void UnitEngine::runFast(const FastOp* op, int& pendingJump, int cycleMs,
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
                                           &&bitStatements,
                                           &&bitStatementsWithoutEdges,
                                           &&wordStatements,
                                           &&end};
    static_assert(std::size(handlers) == FastHandlerCount);
    if (handlerTable) {
        *handlerTable = handlers;
        return;
    }
    FastContext c; // the branches are written before they are read
    c.engine = this;
    c.pendingJump = &pendingJump;
    c.cycleMs = cycleMs;
    c.depth = 0;
    c.a = 0;
    c.b = 0;
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

void UnitEngine::compileSteps() {
    using Kind = ScanMachineCode::Kind;
    using Instruction = ScanMachineCode::Instruction;
    static constexpr auto calls = []<std::size_t... kind>(std::index_sequence<kind...>) {
        return std::array<ScanMachineCode::Handler, sizeof...(kind)>{
            &fastCall<static_cast<int>(kind)>...};
    }
    (std::make_index_sequence<FastHandlerCount>());
    static_assert(offsetof(EdgeState, seen) == 0 && offsetof(EdgeState, last) == 1);
    static_assert(offsetof(FastContext::Branch, any) == 4);
    constexpr auto slotA = static_cast<std::int32_t>(offsetof(FastContext, a));
    constexpr auto slotB = static_cast<std::int32_t>(offsetof(FastContext, b));
    constexpr int maxDepth = std::size(FastContext{}.branches);
    m_machineCode.reset();
    std::uint8_t* ditto = &m_memory.systemMemories[kDitto];
    std::vector<ScanMachineCode::Run> runs;
    runs.reserve(m_steps.size());
    for (const StepRun& step : m_steps) {
        ScanMachineCode::Run& run = runs.emplace_back();
        int depth = 0;
        for (std::uint32_t i = step.first; i < step.first + step.count; ++i) {
            const Decoded& d = m_code[i];
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
                run.push_back({.kind = Kind::Call, .handler = calls[handler], .place = &d});
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
                    in.state = &m_edges[d.slot];
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
                    return; // not a program the compiler makes: interpreted
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
                if (!compileArithmetic(d, run))
                    call(FArith);
                break;
            case HandlerCount:
                break;
            }
        }
    }
    m_machineCode = ScanMachineCode::compile(runs, &m_memory);
}

// Register arithmetic other than a division, in line; false for the rest.
bool UnitEngine::compileArithmetic(const Decoded& d, ScanMachineCode::Run& run) {
    using Operation = ScanMachineCode::Operation;
    constexpr auto a = static_cast<std::int32_t>(offsetof(FastContext, a));
    constexpr auto b = static_cast<std::int32_t>(offsetof(FastContext, b));
    constexpr std::int32_t current = ScanMachineCode::kCurrent;
    constexpr std::int32_t constant = ScanMachineCode::kConstant;
    if (d.refKind != static_cast<std::uint8_t>(WordRef::Kind::Register) || d.dropWrite)
        return false;
    ScanMachineCode::Instruction in{.kind = ScanMachineCode::Kind::Arithmetic,
                                    .place = d.ref,
                                    .state = &m_memory.systemMemories[kOverflow]};
    const auto set = [&in](std::int32_t x, Operation operation, std::int32_t y, int value = 0) {
        in.slot = x;
        in.operation = operation;
        in.slot2 = y;
        in.constant = value;
    };
    switch (static_cast<ArithOp>(d.aux)) {
    case ArithOp::Increment:
        set(current, Operation::Add, constant, 1);
        break;
    case ArithOp::Decrement:
        set(current, Operation::Add, constant, -1);
        break;
    case ArithOp::Add:
        set(current, Operation::Add, a);
        break;
    case ArithOp::Sub:
        set(current, Operation::Subtract, a);
        break;
    case ArithOp::Mul:
        set(current, Operation::Multiply, a);
        break;
    case ArithOp::Copy:
        set(a, Operation::Add, constant);
        break;
    case ArithOp::AddAB:
        set(a, Operation::Add, b);
        break;
    case ArithOp::SubAB:
        set(a, Operation::Subtract, b);
        break;
    case ArithOp::MulAB:
        set(a, Operation::Multiply, b);
        break;
    case ArithOp::Div:
    case ArithOp::DivAB:
        return false;
    }
    run.push_back(in);
    return true;
}

bool UnitEngine::timer(const Decoded& in, bool input, int cycleMs) {
    auto& freeze = m_memory.systemMemories[kTimerFreeze];
    const std::int64_t dt = freeze ? 0 : cycleMs;
    freeze = 0; // SM_TimerFreeze holds the next timer in the code only
    const std::int64_t preset =
        10 * ((in.flags & compiler::ConstantOperand) ? in.constant : in.readWord());
    return m_timers[in.slot].run(input, in.aux, preset, in.flags & compiler::Negated, dt, m_scan);
}

void UnitEngine::arithmetic(const Decoded& in, std::int64_t a, std::int64_t b) {
    auto& sm = m_memory.systemMemories;
    const bool wide = in.wideWord();
    // The manual: a register saturates at 32767 / -32768, a double register at ±2147483647.
    const std::int64_t low = wide ? -2147483647 : -32768;
    const std::int64_t high = wide ? 2147483647 : 32767;
    const std::int64_t current = in.readWord();
    const auto op = static_cast<ArithOp>(in.aux);
    const bool division = isDivision(op);
    std::int64_t result = division ? 0 : undividedResult(op, current, a, b);
    const std::int64_t dividend = op == ArithOp::Div ? current : a;
    const std::int64_t divisor = op == ArithOp::Div ? a : b;
    if (division) {
        sm[kDivByZero] = divisor == 0;
        if (divisor == 0) {
            result = 0;
        } else {
            result = dividend / divisor;
            m_memory.systemRegisters[kRemain] = static_cast<std::int32_t>(dividend % divisor);
        }
    }
    sm[kOverflow] = result < low || result > high;
    if (!in.dropWrite) // a forced register keeps its value
        in.writeWord(std::clamp(result, low, high));
}

} // namespace rs::sim
