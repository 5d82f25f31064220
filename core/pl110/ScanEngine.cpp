// SPDX-License-Identifier: GPL-3.0-or-later
#include "ScanEngine.h"

#include "sim/Conduction.h"

#include <algorithm>
#include <limits>

namespace rs::pl110 {

namespace {

Address special(int word, int bit) {
    return {Area::SpecialMarker, Width::Bit, word, bit};
}

Address specialWord(int word) {
    return {Area::SpecialMarker, Width::Word, word, -1};
}

std::int32_t saturated(std::int64_t value) {
    return static_cast<std::int32_t>(std::clamp<std::int64_t>(value, kWordMin, kWordMax));
}

void forEachRung(const std::vector<Line>& lines, auto&& action) {
    for (const Line& line : lines)
        if (const auto* rung = std::get_if<Rung>(&line.body))
            action(*rung);
}

} // namespace

int milliseconds(TimeBase base) {
    switch (base) {
    case TimeBase::Ms10:
        return 10;
    case TimeBase::Ms100:
        return 100;
    case TimeBase::S1:
        return 1000;
    }
    return 100;
}

Memory::Memory() {
    for (const AreaInfo& info : areaTable())
        words[static_cast<std::size_t>(info.area)].assign(
            static_cast<std::size_t>(wordCount(info.area)), 0);
}

bool Memory::bit(const Address& address) const {
    if (address.area == Area::Timer && address.width == Width::Bit)
        return timerContacts[static_cast<std::size_t>(address.number - 1)];
    if (address.area == Area::Counter && address.width == Width::Bit)
        return counterContacts[static_cast<std::size_t>(address.number - 1)];
    const MemoryPlace place = memoryPlace(address);
    return (words[static_cast<std::size_t>(address.area)][static_cast<std::size_t>(place.word)] >>
            place.bit) &
           1U;
}

void Memory::setBit(const Address& address, bool value) {
    if (address.area == Area::Timer && address.width == Width::Bit) {
        timerContacts[static_cast<std::size_t>(address.number - 1)] = value;
        return;
    }
    if (address.area == Area::Counter && address.width == Width::Bit) {
        counterContacts[static_cast<std::size_t>(address.number - 1)] = value;
        return;
    }
    const MemoryPlace place = memoryPlace(address);
    std::uint16_t& word =
        words[static_cast<std::size_t>(address.area)][static_cast<std::size_t>(place.word)];
    const auto mask = static_cast<std::uint16_t>(1U << place.bit);
    word = static_cast<std::uint16_t>(value ? word | mask : word & ~mask);
}

std::int32_t Memory::value(const Address& address) const {
    const auto& area = words[static_cast<std::size_t>(address.area)];
    const auto word = static_cast<std::size_t>(memoryPlace(address).word);
    if (address.width == Width::Double)
        return static_cast<std::int32_t>((static_cast<std::uint32_t>(area[word]) << 16) |
                                         area[word + 1]);
    return static_cast<std::int16_t>(area[word]);
}

void Memory::setValue(const Address& address, std::int64_t value) {
    auto& area = words[static_cast<std::size_t>(address.area)];
    const auto word = static_cast<std::size_t>(memoryPlace(address).word);
    const auto bits = static_cast<std::uint32_t>(static_cast<std::uint64_t>(value));
    if (address.width == Width::Double) {
        area[word] = static_cast<std::uint16_t>(bits >> 16);
        area[word + 1] = static_cast<std::uint16_t>(bits & 0xFFFF);
    } else {
        area[word] = static_cast<std::uint16_t>(bits & 0xFFFF);
    }
}

ScanEngine::ScanEngine(Program program, int cycleMs)
    : m_program(std::move(program)), m_cycleMs(std::max(1, cycleMs)) {
    const auto sized = [](const std::vector<Line>& lines) {
        std::vector<RungState> states;
        forEachRung(lines, [&](const Rung& rung) {
            RungState state;
            state.edges.assign(
                rung.condition ? static_cast<std::size_t>(ladder::nodeCount(*rung.condition)) : 0U,
                0);
            states.push_back(std::move(state));
        });
        return states;
    };
    m_init = sized(m_program.init);
    m_main = sized(m_program.main);
    const auto mark = [&](const Rung& rung) {
        const std::size_t elements =
            1 +
            (rung.condition ? static_cast<std::size_t>(ladder::nodeCount(*rung.condition)) : 0U);
        m_marks.push_back({false, false, std::vector<std::uint8_t>(elements, 0),
                           std::vector<std::uint8_t>(elements, 0)});
    };
    forEachRung(m_program.init, mark);
    forEachRung(m_program.main, mark);
    const auto counters = [&](const Rung& rung) {
        if (rung.output.kind == OutputKind::Counter)
            m_counterTypes[static_cast<std::size_t>(rung.output.target.address.number - 1)] =
                rung.output.counter;
    };
    forEachRung(m_program.init, counters);
    forEachRung(m_program.main, counters);
    reset();
}

void ScanEngine::reset() {
    m_memory = Memory();
    m_timers = {};
    for (auto* states : {&m_init, &m_main})
        for (RungState& state : *states) {
            std::fill(state.edges.begin(), state.edges.end(), 0);
            state.coilWasOn = false;
        }
    m_forces.clear();
    m_scans = 0;
    m_timeMs = 0;
    // Start values the datasheet gives (docs/pl110.md, "Power on").
    m_memory.setBit(special(0, 0), true);    // RUN
    m_memory.setValue(specialWord(16), 100); // timed interrupt intervals
    m_memory.setValue(specialWord(17), 100);
    m_memory.setValue(specialWord(38), 10); // input filter, ms
    m_memory.setValue(specialWord(39), 5);  // analogue values averaged
    for (int input = 0; input < 4; ++input)
        m_memory.setValue(specialWord(45 + 2 * input), 1000); // AI range maximum
    m_memory.setValue(specialWord(61), 100);                  // AQ1 at 10 V
    m_memory.setValue(specialWord(71), 19200);
    m_memory.setValue(specialWord(81), 19200);
    m_memory.setValue(specialWord(91), 57600);
}

void ScanEngine::specialMarkersAtScanStart() {
    m_memory.setBit(special(0, 1), m_scans == 0);
    m_memory.setBit(special(0, 2), m_timeMs % 60000 < 30000);
    m_memory.setBit(special(0, 3), m_timeMs % 1000 < 500);
    m_memory.setBit(special(0, 4), m_scans % 2 == 0);
    const int scanTime = std::min(m_cycleMs * 10, kWordMax); // 100 µs units
    for (int word : {6, 7, 8})
        m_memory.setValue(specialWord(word), scanTime);
    // TEST mode: the inputs on the terminals come from SM37 instead.
    if (m_memory.bit(special(0, 5)))
        for (int input = 0; input < 8; ++input)
            m_memory.setBit({Area::Input, Width::Bit, input + 1, -1},
                            m_memory.bit(special(37, input)));
}

void ScanEngine::scan() {
    specialMarkersAtScanStart();
    applyForces();
    for (RungMarks& marks : m_marks)
        marks.ran = false;
    if (m_scans == 0)
        runLines(m_program.init, m_init, 0);
    runLines(m_program.main, m_main, m_init.size());
    countersAtScanEnd();
    applyForces();
    ++m_scans;
    m_timeMs += m_cycleMs;
}

void ScanEngine::runLines(const std::vector<Line>& lines, std::vector<RungState>& states,
                          std::size_t firstMark) {
    std::size_t index = 0;
    forEachRung(lines, [&](const Rung& rung) {
        RungMarks& marks = m_marks[firstMark + index];
        RungState& state = states[index++];
        int node = 0;
        const bool power =
            rung.condition ? evaluate(*rung.condition, true, state, node, marks) : true;
        output(rung.output, power, state);
        if (!m_forces.empty())
            applyForces();
        marks.ran = true;
        marks.energised = power;
        marks.power[0] = power ? 1 : 0;
        marks.states[0] = outputState(rung.output, power);
    });
}

void ScanEngine::setCycleMs(int cycleMs) {
    m_cycleMs = std::max(1, cycleMs);
}

std::int64_t ScanEngine::value(const Address& address) const {
    return address.width == Width::Bit ? std::int64_t{m_memory.bit(address)}
                                       : m_memory.value(address);
}

void ScanEngine::set(const Address& address, std::int64_t value) {
    if (address.area == Area::Input || address.area == Area::AnalogInput) {
        if (address.width == Width::Bit)
            m_memory.setBit(address, value != 0);
        else
            m_memory.setValue(address, value);
        return;
    }
    force(address, value);
}

void ScanEngine::force(const Address& address, std::int64_t value) {
    m_forces[address] = value;
    applyForces();
}

void ScanEngine::release(const Address& address) {
    m_forces.erase(address);
}

void ScanEngine::applyForces() {
    for (const auto& [address, value] : m_forces) {
        if (address.width == Width::Bit)
            m_memory.setBit(address, value != 0);
        else
            m_memory.setValue(address, value);
    }
}

// The power leaving a circuit that `power` reaches. Every element is
// evaluated every scan, so edges see every change of what reaches them.
bool ScanEngine::evaluate(const Circuit& circuit, bool power, RungState& state, int& node,
                          RungMarks& marks) {
    const auto self = static_cast<std::size_t>(node++);
    // The ladder numbers elements from 1; 0 is the output.
    const auto mark = [&](bool out, bool closed) {
        marks.power[self + 1] = out ? 1 : 0;
        marks.states[self + 1] = closed ? sim::ElementState::Closed : 0;
        return out;
    };
    switch (circuit.kind) {
    case Circuit::Kind::Series:
        for (const Circuit& part : circuit.parts)
            power = evaluate(part, power, state, node, marks);
        return mark(power, power);
    case Circuit::Kind::Parallel: {
        bool any = false;
        for (const Circuit& part : circuit.parts)
            any = evaluate(part, power, state, node, marks) || any;
        return mark(any, any);
    }
    case Circuit::Kind::Element:
        break;
    }
    const Element& element = circuit.element;
    switch (element.kind) {
    case ElementKind::NormallyOpen: {
        const bool closed = m_memory.bit(element.operand.address);
        return mark(power && closed, closed);
    }
    case ElementKind::NormallyClosed: {
        const bool closed = !m_memory.bit(element.operand.address);
        return mark(power && closed, closed);
    }
    case ElementKind::Compare: {
        const std::int32_t a = read(element.left);
        const std::int32_t b = read(element.right);
        bool holds = false;
        switch (element.compare) {
        case CompareOp::Equal:
            holds = a == b;
            break;
        case CompareOp::NotEqual:
            holds = a != b;
            break;
        case CompareOp::Greater:
            holds = a > b;
            break;
        case CompareOp::Less:
            holds = a < b;
            break;
        case CompareOp::GreaterEqual:
            holds = a >= b;
            break;
        case CompareOp::LessEqual:
            holds = a <= b;
            break;
        }
        return mark(power && holds, holds);
    }
    case ElementKind::Not:
        return mark(!power, !power);
    case ElementKind::RisingEdge:
    case ElementKind::FallingEdge: {
        const bool before = state.edges[self] != 0;
        state.edges[self] = power ? 1 : 0;
        const bool out =
            element.kind == ElementKind::RisingEdge ? power && !before : !power && before;
        return mark(out, out);
    }
    }
    return false;
}

std::int32_t ScanEngine::read(const Value& value) const {
    return value.isConstant() ? value.constant : m_memory.value(value.operand->address);
}

void ScanEngine::output(const Output& out, bool power, RungState& state) {
    const Address& target = out.target.address;
    switch (out.kind) {
    case OutputKind::Coil:
        if (target.area == Area::Bistable) {
            // Each energisation changes the relay once (docs/pl110.md, A10).
            if (power && !state.coilWasOn)
                m_memory.setBit(target, !m_memory.bit(target));
            state.coilWasOn = power;
        } else {
            m_memory.setBit(target, power);
        }
        return;
    case OutputKind::SetBit:
    case OutputKind::ResetBit:
        if (power)
            m_memory.setBit(target, out.kind == OutputKind::SetBit);
        return;
    case OutputKind::Timer:
        m_timerRunning = timer(out, power).second;
        return;
    case OutputKind::Counter:
        counter(out, power, state);
        return;
    case OutputKind::Move:
        if (power)
            m_memory.setValue(target, read(out.left));
        return;
    case OutputKind::Formula:
        break;
    }
    if (!power)
        return;
    const std::int64_t a = read(out.left);
    const std::int64_t b = read(out.right);
    std::int64_t result = 0;
    switch (out.formula) {
    case FormulaOp::Add:
        result = a + b;
        break;
    case FormulaOp::Sub:
        result = a - b;
        break;
    case FormulaOp::Mul:
        result = a * b;
        break;
    case FormulaOp::Div:
        if (b == 0)
            return; // the destination keeps its value (docs/pl110.md, G2)
        result = a / b;
        break;
    case FormulaOp::Or:
        result = a | b;
        break;
    case FormulaOp::And:
        result = a & b;
        break;
    case FormulaOp::Xor:
        result = a ^ b;
        break;
    case FormulaOp::ShiftLeft:
    case FormulaOp::ShiftRight: {
        // Shifts of the operand's bits as stored; counts outside 0-31 give 0.
        const std::uint32_t bits = static_cast<std::uint32_t>(a);
        if (b < 0 || b > 31)
            result = 0;
        else if (out.formula == FormulaOp::ShiftLeft)
            result = static_cast<std::int64_t>(bits << b);
        else
            result = static_cast<std::int64_t>(static_cast<std::int32_t>(a) >> b);
        break;
    }
    }
    m_memory.setValue(target, result);
}

std::pair<bool, bool> ScanEngine::timer(const Output& out, bool power) {
    const int number = out.target.address.number;
    const Address value{Area::Timer, Width::Word, number, -1};
    const Address preset{Area::TimerPreset, Width::Word, number, -1};
    m_memory.setValue(preset, read(out.preset));
    TimerState& t = m_timers[static_cast<std::size_t>(number - 1)];
    const int base = milliseconds(out.base);
    // Adds one scan's time to the value, in whole units of the base, up to 32767.
    const auto advance = [&] {
        t.remainderMs += m_cycleMs;
        const std::int64_t units = t.remainderMs / base;
        t.remainderMs %= base;
        m_memory.setValue(value, std::min<std::int64_t>(kWordMax, m_memory.value(value) + units));
    };
    const std::int32_t limit = m_memory.value(preset);
    bool contact = false;
    switch (out.timer) {
    case TimerType::OnDelay:
        if (!power) {
            m_memory.setValue(value, 0);
            t.remainderMs = 0;
        } else if (t.wasOn) {
            advance();
        }
        contact = power && m_memory.value(value) >= limit;
        break;
    case TimerType::Retentive:
        if (power && t.wasOn)
            advance();
        contact = m_memory.value(value) >= limit;
        break;
    case TimerType::OffDelay:
        if (power) {
            m_memory.setValue(value, 0);
            t.remainderMs = 0;
            t.counting = false;
        } else if (t.wasOn) {
            t.counting = true; // the falling edge starts the count from 0
        } else if (t.counting) {
            advance();
        }
        if (t.counting && m_memory.value(value) >= limit) {
            m_memory.setValue(value, limit);
            t.counting = false;
        }
        contact = power || t.counting;
        break;
    }
    t.wasOn = power;
    m_memory.setBit({Area::Timer, Width::Bit, number, -1}, contact);
    const bool running = out.timer == TimerType::OffDelay ? t.counting : power && !contact;
    return {contact, running};
}

void ScanEngine::counter(const Output& out, bool power, RungState& state) {
    const int number = out.target.address.number;
    const Address value{Area::Counter, Width::Word, number, -1};
    const Address preset{Area::CounterPreset, Width::Word, number, -1};
    m_memory.setValue(preset, read(out.preset));
    const bool rising = power && !state.coilWasOn;
    state.coilWasOn = power;
    const std::int32_t now = m_memory.value(value);
    switch (out.input) {
    case CounterInput::Up:
        if (rising)
            m_memory.setValue(value, saturated(std::int64_t{now} + 1));
        break;
    case CounterInput::Down:
        if (rising)
            m_memory.setValue(value, out.counter == CounterType::Down
                                         ? std::max(0, now - 1)
                                         : saturated(std::int64_t{now} - 1));
        break;
    case CounterInput::Reset:
        if (power && out.counter == CounterType::Up) {
            m_memory.setValue(value, 0);
        } else if (power) {
            m_memory.setValue(value, m_memory.value(preset));
            m_memory.setBit({Area::Counter, Width::Bit, number, -1}, false);
        }
        break;
    }
}

std::uint8_t ScanEngine::outputState(const Output& out, bool power) const {
    switch (out.kind) {
    case OutputKind::Coil:
    case OutputKind::SetBit:
    case OutputKind::ResetBit:
        return m_memory.bit(out.target.address) ? sim::ElementState::Closed : 0;
    case OutputKind::Timer:
        return static_cast<std::uint8_t>(
            (m_memory.bit(out.target.address) ? sim::ElementState::Closed : 0) |
            (m_timerRunning ? sim::ElementState::Running : 0));
    case OutputKind::Counter:
        return m_memory.bit(out.target.address) ? sim::ElementState::Closed : 0;
    case OutputKind::Move:
    case OutputKind::Formula:
        break;
    }
    return power ? sim::ElementState::Closed : 0;
}

// Counters compare with their presets once, at the end of the scan.
void ScanEngine::countersAtScanEnd() {
    for (int number = 1; number <= 16; ++number) {
        const auto type = m_counterTypes[static_cast<std::size_t>(number - 1)];
        if (!type)
            continue;
        const std::int32_t value = m_memory.value({Area::Counter, Width::Word, number, -1});
        const std::int32_t preset = m_memory.value({Area::CounterPreset, Width::Word, number, -1});
        const bool on = *type == CounterType::Down ? value == 0 : value >= preset;
        m_memory.setBit({Area::Counter, Width::Bit, number, -1}, on);
    }
}

} // namespace rs::pl110
