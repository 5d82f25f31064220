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

void UnitEngine::decode() {
    m_code.clear();
    m_code.reserve(m_image.code.size());
    for (const auto& in : m_image.code) {
        Decoded d{in.op, in.flags, in.aux, in.slot, in.constant, {}, {}, false};
        switch (in.op) {
        case Op::Contact:
        case Op::Edge:
            d.bit = decodeBit(in.operand, false);
            break;
        case Op::Coil:
        case Op::Set:
        case Op::Reset:
        case Op::Toggle:
            d.bit = decodeBit(in.operand, true);
            break;
        case Op::LoadA:
        case Op::LoadB:
        case Op::Timer:
            if (!(in.flags & compiler::ConstantOperand))
                d.word = decodeWord(in.operand);
            break;
        case Op::Arith:
            d.word = decodeWord(in.operand);
            d.dropWrite = m_forces.count(in.operand) != 0;
            break;
        default:
            break;
        }
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
    std::fill(m_timers.begin(), m_timers.end(), TimerState{});
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
    std::fill(m_conduction.begin(), m_conduction.end(), Conduction::NotRun);

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
        runStep(sequence.stepIndex[sequence.active], pendingJump, cycleMs);
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
            m_code[i].bit.write(false);
}

void UnitEngine::runStep(int index, int& pendingJump, int cycleMs) {
    const StepRun& step = m_steps[static_cast<std::size_t>(index)];
    auto& sm = m_memory.systemMemories;
    struct Branch {
        bool in;
        bool any;
    };
    Branch branches[64];
    int depth = 0;
    bool power = true;
    std::int64_t a = 0;
    std::int64_t b = 0;
    const std::uint32_t end = step.first + step.count;
    for (std::uint32_t i = step.first; i < end; ++i) {
        const Decoded& in = m_code[i];
        const bool negated = in.flags & compiler::Negated;
        switch (in.op) {
        case Op::Rung:
            power = true;
            break;
        case Op::Contact:
            power = power && (in.bit.read() != negated);
            break;
        case Op::Edge: {
            EdgeState& edge = m_edges[in.slot];
            const bool value = in.bit.read() != bool(in.flags & compiler::OperandNegated);
            bool seen = false;
            if (edge.seen)
                seen =
                    (in.flags & compiler::Rising) ? (value && !edge.last) : (!value && edge.last);
            edge.seen = true;
            edge.last = value;
            power = power && (seen != negated);
            break;
        }
        case Op::Timer:
            power = timer(in, power, cycleMs);
            break;
        case Op::LoadA:
            a = (in.flags & compiler::ConstantOperand) ? in.constant : in.word.read();
            break;
        case Op::LoadB:
            b = (in.flags & compiler::ConstantOperand) ? in.constant : in.word.read();
            break;
        case Op::Compare: {
            bool result = false;
            switch (static_cast<lang::CompareOp>(in.aux)) {
            case lang::CompareOp::Equal:
                result = a == b;
                break;
            case lang::CompareOp::Greater:
                result = a > b;
                break;
            case lang::CompareOp::Less:
                result = a < b;
                break;
            case lang::CompareOp::GreaterEqual:
                result = a >= b;
                break;
            case lang::CompareOp::LessEqual:
                result = a <= b;
                break;
            }
            power = power && (result != negated);
            break;
        }
        case Op::BranchOpen:
            branches[depth++] = {power, false};
            break;
        case Op::BranchNext:
            branches[depth - 1].any = branches[depth - 1].any || power;
            power = branches[depth - 1].in;
            break;
        case Op::BranchClose:
            power = branches[--depth].any || power;
            break;
        case Op::Coil:
            in.bit.write(power);
            sm[kDitto] = power;
            break;
        case Op::Set:
            if (power)
                in.bit.write(true);
            sm[kDitto] = power;
            break;
        case Op::Reset:
            if (power)
                in.bit.write(false);
            sm[kDitto] = power;
            break;
        case Op::Toggle:
            if (power)
                in.bit.write(!in.bit.read());
            sm[kDitto] = power;
            break;
        case Op::Jump:
            if (power)
                pendingJump = in.slot; // the last jump taken in the step wins
            break;
        case Op::SequenceReset:
            if (power && in.slot < 10)
                m_sequences[in.slot].resetRequested = true;
            break;
        case Op::Arith:
            if (power)
                arithmetic(in, a, b);
            break;
        }
        m_conduction[i] = power ? Conduction::On : Conduction::Off;
    }
}

bool UnitEngine::timer(const Decoded& in, bool input, int cycleMs) {
    TimerState& t = m_timers[in.slot];
    // A timer whose line did not run in the previous scan starts afresh.
    if (t.lastScan + 1 != m_scan)
        t = TimerState{};
    t.lastScan = m_scan;
    auto& freeze = m_memory.systemMemories[kTimerFreeze];
    const std::int64_t dt = freeze ? 0 : cycleMs;
    freeze = 0; // SM_TimerFreeze holds the next timer in the code only
    const std::int64_t preset =
        10 * ((in.flags & compiler::ConstantOperand) ? in.constant : in.word.read());
    const bool rising = input && !t.lastInput;
    const bool falling = !input && t.lastInput;
    switch (static_cast<lang::TimerKind>(in.aux)) {
    case lang::TimerKind::OnDelay:
        t.elapsedMs = input ? (rising ? 0 : t.elapsedMs + dt) : 0;
        t.output = input && t.elapsedMs >= preset;
        break;
    case lang::TimerKind::Pulse:
        if (rising) {
            t.running = true;
            t.elapsedMs = 0;
        } else if (input && t.running) {
            t.elapsedMs += dt;
        }
        if (!input || t.elapsedMs >= preset)
            t.running = false;
        t.output = input && t.running;
        break;
    case lang::TimerKind::OffDelay:
        if (input) {
            t.running = true;
            t.elapsedMs = 0;
        } else if (t.running) {
            t.elapsedMs = falling ? 0 : t.elapsedMs + dt;
            if (t.elapsedMs >= preset)
                t.running = false;
        }
        t.output = t.running;
        break;
    }
    t.lastInput = input;
    const bool negated = in.flags & compiler::Negated;
    return negated ? input && !t.output : t.output;
}

void UnitEngine::arithmetic(const Decoded& in, std::int64_t a, std::int64_t b) {
    auto& sm = m_memory.systemMemories;
    const WordRef& target = in.word;
    const bool wide = target.isDouble() || target.kind == WordRef::Kind::Wide;
    // The manual: a register saturates at 32767 / -32768, a double register at ±2147483647.
    const std::int64_t low = wide ? -2147483647 : -32768;
    const std::int64_t high = wide ? 2147483647 : 32767;
    const std::int64_t current = target.read();
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
        target.write(std::clamp(result, low, high));
}

} // namespace rs::sim
