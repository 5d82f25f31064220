#include "UnitEngine.h"

#include "lang/Ast.h"

#include <algorithm>
#include <cstring>

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

} // namespace

UnitEngine::UnitEngine(compiler::UnitImage image, const Bus& published)
    : m_image(std::move(image)), m_bus(published) {
    for (const auto& step : m_image.steps) {
        auto& sequence = m_sequences[step.sequence];
        if (sequence.stepIndex.empty())
            sequence.stepIndex.assign(kMaxStep + 1, -1);
        sequence.stepIndex[step.step] = static_cast<int>(m_steps.size());
        m_steps.push_back({step.sequence, step.step, step.first, step.count});
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

BitRef UnitEngine::decodeBit(const lang::Address& address, bool forWriting) {
    if (address.unit != m_image.station) {
        // Another unit's global variable, as it published it.
        auto& remote = const_cast<UnitMemory&>(m_bus[static_cast<std::size_t>(address.unit) % 32]);
        return bitRef(remote, address, false);
    }
    if (forWriting && m_forces.count(address))
        return bitRef(m_sink, address, true);
    return bitRef(m_memory, address, forWriting);
}

WordRef UnitEngine::decodeWord(const lang::Address& address) {
    if (address.unit != m_image.station)
        return wordRef(const_cast<UnitMemory&>(m_bus[static_cast<std::size_t>(address.unit) % 32]),
                       address);
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
    m_forces[address] = value;
    write(address, value);
    decode();
}

void UnitEngine::release(const lang::Address& address) {
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
    // Only the steps that ran last time have marks to clear.
    for (int index : m_ranSteps) {
        const StepRun& step = m_steps[static_cast<std::size_t>(index)];
        std::fill_n(m_conduction.begin() + step.first, step.count, Conduction::NotRun);
    }
    m_ranSteps.clear();

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
        runStep(stepIndex, pendingJump, cycleMs);
        m_ranSteps.push_back(stepIndex);
        if (pendingJump >= 0 && !held) {
            leaveStep(sequence.stepIndex[sequence.active]);
            sequence.active = pendingJump;
            sequence.stepNew = true;
        }
    }
}

void UnitEngine::leaveStep(int index) {
    const StepRun& step = m_steps[static_cast<std::size_t>(index)];
    for (std::uint32_t i = step.first; i < step.first + step.count; ++i)
        if (m_code[i].op == Op::Coil)
            m_code[i].writeBit(false);
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
edge : {
    EdgeState& state = m_edges[in->slot];
    const bool value = in->readBit() != bool(in->flags & compiler::OperandNegated);
    bool seen = false;
    if (state.seen)
        seen = (in->flags & compiler::Rising) ? (value && !state.last) : (!value && state.last);
    state.seen = true;
    state.last = value;
    power &= static_cast<unsigned>(seen) ^ RS_NEGATED;
    RS_NEXT();
}
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
    std::int64_t result = 0;
    bool division = false;
    std::int64_t dividend = 0;
    std::int64_t divisor = 0;
    switch (static_cast<ArithOp>(in.aux)) {
    case ArithOp::Increment:
        result = current + 1;
        break;
    case ArithOp::Decrement:
        result = current - 1;
        break;
    case ArithOp::Add:
        result = current + a;
        break;
    case ArithOp::Sub:
        result = current - a;
        break;
    case ArithOp::Mul:
        result = current * a;
        break;
    case ArithOp::Div:
        division = true;
        dividend = current;
        divisor = a;
        break;
    case ArithOp::Copy:
        result = a;
        break;
    case ArithOp::AddAB:
        result = a + b;
        break;
    case ArithOp::SubAB:
        result = a - b;
        break;
    case ArithOp::MulAB:
        result = a * b;
        break;
    case ArithOp::DivAB:
        division = true;
        dividend = a;
        divisor = b;
        break;
    }
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
