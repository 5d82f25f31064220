// SPDX-License-Identifier: GPL-3.0-or-later
#include "ScanModel.h"

#include "compiler/SystemInstruction.h"
#include "project/AsiOptions.h"
#include "sim/UnitMemory.h"
#include "sim/engine/InstructionMeaning.h"

#include <algorithm>
#include <set>

namespace rs::prove {

namespace {

using compiler::Op;
using lang::AddressKind;
using sim::UnitMemory;

// Where a variable lives in sim::UnitMemory, as one key: an area and an index.
enum class Area : std::uint8_t {
    Input,
    Output,
    Memory,
    GlobalMemory,
    SystemMemory,
    Register,
    SystemRegister,
    Analog,
    AsiSafe,
    AsiIn,
    AsiOut,
};

using Cell = std::uint32_t;

constexpr Cell cell(Area area, int index) {
    return (static_cast<Cell>(area) << 16) | static_cast<Cell>(index);
}
constexpr Area areaOf(Cell c) {
    return static_cast<Area>(c >> 16);
}
constexpr int indexOf(Cell c) {
    return static_cast<int>(c & 0xFFFF);
}

int areaSize(Area area) {
    switch (area) {
    case Area::Input:
    case Area::Output:
        return UnitMemory::kTerminals;
    case Area::Memory:
        return UnitMemory::kMemories;
    case Area::GlobalMemory:
        return UnitMemory::kGlobalMemories;
    case Area::SystemMemory:
        return UnitMemory::kSystemMemories;
    case Area::Register:
        return UnitMemory::kRegisters;
    case Area::SystemRegister:
        return UnitMemory::kSystemRegisters;
    case Area::Analog:
        return UnitMemory::kAnalogInputs;
    case Area::AsiSafe:
        return 32;
    case Area::AsiIn:
    case Area::AsiOut:
        return UnitMemory::kAsiSlaves * 4;
    }
    return 0;
}

int cellWidth(Cell c) {
    switch (areaOf(c)) {
    case Area::Register:
        return 16;
    case Area::SystemRegister:
    case Area::Analog:
        return 32;
    default:
        return 1;
    }
}

// Values the outside world gives (Simulation::set without forcing).
bool isInputCell(Cell c) {
    switch (areaOf(c)) {
    case Area::Input:
    case Area::Analog:
    case Area::AsiSafe:
    case Area::AsiIn:
        return true;
    case Area::SystemRegister:
        return indexOf(c) >= 40 && indexOf(c) <= 46;
    default:
        return false;
    }
}

std::int64_t powerOnValue(Cell c) {
    return c == cell(Area::SystemRegister, 40) ? 240 : 0; // 24.0 V
}

// The address a scenario sets to give an input cell its value.
lang::Address inputAddress(int station, Cell c) {
    lang::Address a;
    a.unit = station;
    a.index = indexOf(c);
    switch (areaOf(c)) {
    case Area::Input:
        a.kind = AddressKind::Input;
        break;
    case Area::Analog:
        a.kind = AddressKind::AnalogInput;
        break;
    case Area::AsiSafe:
        a.kind = AddressKind::AsiInput;
        break;
    case Area::AsiIn:
        a.kind = AddressKind::AsiInput;
        a.index = indexOf(c) / 4 % 32;
        a.asiB = indexOf(c) / 4 >= 32;
        a.bit = indexOf(c) % 4 + 1;
        break;
    default:
        a.kind = AddressKind::SystemRegister;
        break;
    }
    return a;
}

// A bit place (sim::bitRef): a byte cell, a register's bit, an analogue
// input read as a bit, or nowhere.
struct BitPlace {
    enum class Kind : std::uint8_t { None, Byte, RegisterBit, Analog } kind = Kind::None;
    Cell cell = 0;
    int bit = 0;
};

BitPlace byteAt(Area area, int index) {
    if (index < 0 || index >= areaSize(area))
        return {};
    return {BitPlace::Kind::Byte, cell(area, index), 0};
}

BitPlace bitPlace(const lang::Address& a, bool forWriting) {
    switch (a.kind) {
    case AddressKind::Input:
        return byteAt(Area::Input, a.index);
    case AddressKind::Output:
        return byteAt(Area::Output, a.index);
    case AddressKind::InputOutput:
        return byteAt(forWriting ? Area::Output : Area::Input, a.index);
    case AddressKind::AnalogInput:
        if (a.index < 0 || a.index >= UnitMemory::kAnalogInputs)
            return {};
        return {BitPlace::Kind::Analog, cell(Area::Analog, a.index), 0};
    case AddressKind::Memory:
        return byteAt(Area::Memory, a.index);
    case AddressKind::GlobalMemory:
        return byteAt(Area::GlobalMemory, a.index);
    case AddressKind::SystemMemory:
        return byteAt(Area::SystemMemory, a.index);
    case AddressKind::RegisterBit:
        if (a.index < 0 || a.index >= UnitMemory::kRegisters || a.bit < 0 || a.bit >= 16)
            return {};
        return {BitPlace::Kind::RegisterBit, cell(Area::Register, a.index), a.bit};
    case AddressKind::AsiInput:
        if (a.bit < 0)
            return byteAt(Area::AsiSafe, a.index);
        [[fallthrough]];
    case AddressKind::AsiOutput: {
        const int slave = a.index + (a.asiB ? 32 : 0);
        if (slave < 0 || slave >= UnitMemory::kAsiSlaves || a.bit < 1 || a.bit > 4)
            return {};
        return byteAt(a.kind == AddressKind::AsiInput ? Area::AsiIn : Area::AsiOut,
                      slave * 4 + a.bit - 1);
    }
    default:
        return {};
    }
}

// A number place (sim::wordRef).
struct WordPlace {
    enum class Kind : std::uint8_t { None, Register, Double, Wide } kind = Kind::None;
    Cell cell = 0; // Double: the low register; the high one follows
};

WordPlace wordPlace(const lang::Address& a) {
    switch (a.kind) {
    case AddressKind::Register:
    case AddressKind::DoubleRegisterLow:
        if (a.index >= 0 && a.index < UnitMemory::kRegisters)
            return {WordPlace::Kind::Register, cell(Area::Register, a.index)};
        return {};
    case AddressKind::DoubleRegisterHigh:
        if (a.index + 1 >= 0 && a.index + 1 < UnitMemory::kRegisters)
            return {WordPlace::Kind::Register, cell(Area::Register, a.index + 1)};
        return {};
    case AddressKind::DoubleRegister:
        if (a.index >= 0 && a.index % 2 == 0 && a.index + 1 < UnitMemory::kRegisters)
            return {WordPlace::Kind::Double, cell(Area::Register, a.index)};
        return {};
    case AddressKind::SystemRegister:
        if (a.index >= 0 && a.index < UnitMemory::kSystemRegisters)
            return {WordPlace::Kind::Wide, cell(Area::SystemRegister, a.index)};
        return {};
    case AddressKind::AnalogInput:
        if (a.index >= 0 && a.index < UnitMemory::kAnalogInputs)
            return {WordPlace::Kind::Wide, cell(Area::Analog, a.index)};
        return {};
    default:
        return {};
    }
}

constexpr Cell kChannelFault = cell(Area::SystemRegister, 16); // SR_ASi_Slave_Chanf
constexpr int kStepNew = 0;
constexpr int kSysInit = 9;
constexpr int kFlashMemories[] = {2, 3, 4, 5, 6};
constexpr int kStepWidth = 9; // step numbers 0-255, as non-negative words

} // namespace

struct ScanModel::Unit {
    const compiler::UnitImage* image = nullptr;
    int station = 0;
    std::set<Cell> stateCells;
    std::map<Cell, Word> current;       // state cells at the start of the scan
    std::map<Cell, Word> now;           // what the scan has written so far
    std::map<Cell, Word> input;         // input cells of this scan
    std::map<Cell, Word> previousInput; // input cells as the last scan had them (the bus)
    std::map<Cell, Word> published;     // with a CAN bus cycle time: what the bus holds
    Lit publishes = kTrue;              // whether this scan's end goes onto the bus
    bool monitoredChannels = false;     // safe AS-i input slaves: SR_ASi_Slave_Chanf is set

    struct Edge {
        Lit seen, last;
    };
    std::vector<Edge> edges, edgesNow;
    struct Timer {
        Word ticks;
        Lit lastInput, running, ranLast;
        std::int64_t cap = 0;
        bool used = false;
    };
    std::vector<Timer> timers, timersNow;
    struct Sequence {
        std::vector<int> steps;            // step numbers, ascending
        std::vector<std::size_t> stepCode; // index in image->steps, by steps
        Word active;
        Lit stepNew, resetRequested;
        Word activeNow;
        Lit stepNewNow, resetNow;
    };
    std::map<int, Sequence> sequences;
};

// Runs the instructions symbolically; one per ScanModel.
class ScanBuilder {
public:
    explicit ScanBuilder(ScanModel& model) : m(model), w(model.m_words), g(model.m_graph) {}

    void prepare(ScanModel::Unit& unit);
    void scan(ScanModel::Unit& unit);
    void finish();

    Word readCell(ScanModel::Unit& unit, Cell c);
    Word readRemote(int station, Cell c);
    Lit readBit(ScanModel::Unit& unit, const lang::Address& a);
    Word readWord(ScanModel::Unit& unit, const lang::Address& a);

private:
    ScanModel::Unit* unitAt(int station) {
        for (auto& unit : m.m_units)
            if (unit->station == station)
                return unit.get();
        return nullptr;
    }
    Word state(int width, std::int64_t initial) { return m.addState(width, initial); }
    Word inputWord(ScanModel::Unit& unit, Cell c);
    Word bitWord(Lit bit) { return w.bit(bit); }
    Lit bitOf(const BitPlace& place, const Word& value) {
        switch (place.kind) {
        case BitPlace::Kind::Byte:
            return value.bits[0];
        case BitPlace::Kind::RegisterBit:
            return value.bits[static_cast<std::size_t>(place.bit)];
        case BitPlace::Kind::Analog:
            return negate(w.isZero(value));
        case BitPlace::Kind::None:
            break;
        }
        return kFalse;
    }
    void write(ScanModel::Unit& unit, Cell c, Lit guard, const Word& value);
    void writeBit(ScanModel::Unit& unit, const lang::Address& a, Lit guard, Lit value);
    // What an output reads of its own variable: the place it writes (an IQ's lamp).
    Lit readOutputBit(ScanModel::Unit& unit, const lang::Address& a) {
        const BitPlace place = bitPlace(a, true);
        return place.kind == BitPlace::Kind::None ? kFalse
                                                  : bitOf(place, readCell(unit, place.cell));
    }
    void writeWord(ScanModel::Unit& unit, const lang::Address& a, Lit guard, const Word& value);
    void runStep(ScanModel::Unit& unit, std::size_t stepCode, Lit guard, Lit& jumped, Word& target);
    void leaveStep(ScanModel::Unit& unit, std::size_t stepCode, Lit guard);
    Lit timer(ScanModel::Unit& unit, const compiler::Instruction& in, Lit guard, Lit input);
    void arithmetic(ScanModel::Unit& unit, const compiler::Instruction& in, Lit guard,
                    const Word& a, const Word& b);
    void abstracted(const ScanModel::Unit& unit, const compiler::Instruction& in,
                    const std::string& what);
    // A value no scenario can set: an input of the model only. A bit for an
    // address that is no number.
    Word freeWord(const lang::Address& address) {
        const WordPlace place = wordPlace(address);
        const int width = place.kind == WordPlace::Kind::None       ? 1
                          : place.kind == WordPlace::Kind::Register ? 16
                                                                    : 32;
        Word word = w.variables(width);
        m.m_inputs.push_back({lang::Address{}, word, width == 1});
        return word;
    }

    ScanModel& m;
    WordBuilder& w;
    AndGraph& g;
    std::set<std::string> m_reported;
};

Word ScanBuilder::inputWord(ScanModel::Unit& unit, Cell c) {
    auto [at, added] = unit.input.try_emplace(c);
    if (added) {
        const int width = cellWidth(c);
        Word word = w.variables(width);
        if (width == 1)
            word.bits.push_back(kFalse);
        at->second = word;
        m.m_inputs.push_back({inputAddress(unit.station, c), word, width == 1});
    }
    return at->second;
}

Word ScanBuilder::readCell(ScanModel::Unit& unit, Cell c) {
    if (auto at = unit.now.find(c); at != unit.now.end())
        return at->second;
    if (isInputCell(c) || (unit.monitoredChannels && c == kChannelFault))
        return inputWord(unit, c);
    if (auto at = unit.current.find(c); at != unit.current.end())
        return at->second;
    return w.constant(powerOnValue(c), cellWidth(c) == 1 ? 2 : cellWidth(c));
}

// Another unit's variable as the bus carries it: what that unit had at the
// end of the last scan it published (Simulation::publish); 0 for a unit that
// is not in the project.
Word ScanBuilder::readRemote(int station, Cell c) {
    ScanModel::Unit* unit = unitAt(station);
    const int width = cellWidth(c) == 1 ? 2 : cellWidth(c);
    if (!unit)
        return w.constant(0, width);
    if (unit->image->canCycleMs != 0) {
        auto [at, added] = unit->published.try_emplace(c);
        if (added) {
            at->second = state(cellWidth(c), powerOnValue(c));
            if (cellWidth(c) == 1)
                at->second.bits.push_back(kFalse);
        }
        return at->second;
    }
    if (isInputCell(c) || (unit->monitoredChannels && c == kChannelFault)) {
        auto [at, added] = unit->previousInput.try_emplace(c);
        if (added) {
            at->second = state(cellWidth(c), powerOnValue(c));
            if (cellWidth(c) == 1)
                at->second.bits.push_back(kFalse);
        }
        return at->second;
    }
    if (auto at = unit->current.find(c); at != unit->current.end())
        return at->second;
    return w.constant(powerOnValue(c), width);
}

Lit ScanBuilder::readBit(ScanModel::Unit& unit, const lang::Address& a) {
    const BitPlace place = bitPlace(a, false);
    if (place.kind == BitPlace::Kind::None)
        return kFalse;
    const Word value =
        a.unit == unit.station ? readCell(unit, place.cell) : readRemote(a.unit, place.cell);
    return bitOf(place, value);
}

Word ScanBuilder::readWord(ScanModel::Unit& unit, const lang::Address& a) {
    const WordPlace place = wordPlace(a);
    auto cellValue = [&](Cell c) {
        return a.unit == unit.station ? readCell(unit, c) : readRemote(a.unit, c);
    };
    switch (place.kind) {
    case WordPlace::Kind::None:
        return w.constant(0, 1);
    case WordPlace::Kind::Register:
    case WordPlace::Kind::Wide:
        return cellValue(place.cell);
    case WordPlace::Kind::Double: {
        Word low = cellValue(place.cell);
        const Word high = cellValue(place.cell + 1);
        low.bits.insert(low.bits.end(), high.bits.begin(), high.bits.end());
        return low;
    }
    }
    return w.constant(0, 1);
}

void ScanBuilder::write(ScanModel::Unit& unit, Cell c, Lit guard, const Word& value) {
    const Word before = readCell(unit, c);
    const int width = cellWidth(c) == 1 ? 2 : cellWidth(c);
    Word after = w.extended(w.choose(guard, value, before), width);
    if (cellWidth(c) == 1)
        after.bits[1] = kFalse;
    unit.now[c] = after;
}

void ScanBuilder::writeBit(ScanModel::Unit& unit, const lang::Address& a, Lit guard, Lit value) {
    const BitPlace place = bitPlace(a, true);
    switch (place.kind) {
    case BitPlace::Kind::Byte:
        write(unit, place.cell, guard, bitWord(value));
        break;
    case BitPlace::Kind::RegisterBit: {
        Word word = readCell(unit, place.cell);
        word.bits[static_cast<std::size_t>(place.bit)] = value;
        write(unit, place.cell, guard, word);
        break;
    }
    default:
        break;
    }
}

void ScanBuilder::writeWord(ScanModel::Unit& unit, const lang::Address& a, Lit guard,
                            const Word& value) {
    const WordPlace place = wordPlace(a);
    switch (place.kind) {
    case WordPlace::Kind::Register:
        write(unit, place.cell, guard, w.extended(value, 16));
        break;
    case WordPlace::Kind::Wide:
        write(unit, place.cell, guard, w.extended(value, 32));
        break;
    case WordPlace::Kind::Double: {
        const Word bits = w.extended(value, 32);
        write(unit, place.cell, guard, Word{{bits.bits.begin(), bits.bits.begin() + 16}});
        write(unit, place.cell + 1, guard, Word{{bits.bits.begin() + 16, bits.bits.end()}});
        break;
    }
    case WordPlace::Kind::None:
        break;
    }
}

void ScanBuilder::abstracted(const ScanModel::Unit& unit, const compiler::Instruction& in,
                             const std::string& what) {
    std::string sentence =
        "unit " + std::to_string(unit.station) + " line " + std::to_string(in.line) + ": " + what;
    if (m_reported.insert(sentence).second)
        m.m_abstractions.push_back(sentence);
}

// The cells a unit's scan can change: they are the state.
void ScanBuilder::prepare(ScanModel::Unit& unit) {
    auto& cells = unit.stateCells;
    for (int memory = 0; memory <= 12; ++memory)
        cells.insert(cell(Area::SystemMemory, memory));
    for (int station = 0; station < 32; ++station)
        cells.insert(cell(Area::SystemMemory, 100 + station));
    cells.insert(cell(Area::SystemRegister, sim::engine::kRemain));
    for (const auto& in : unit.image->code) {
        switch (in.op) {
        case Op::Coil:
        case Op::Set:
        case Op::Reset:
        case Op::Toggle:
            if (const BitPlace place = bitPlace(in.operand, true);
                place.kind == BitPlace::Kind::Byte || place.kind == BitPlace::Kind::RegisterBit)
                cells.insert(place.cell);
            break;
        case Op::Arith:
            if (const WordPlace place = wordPlace(in.operand);
                place.kind != WordPlace::Kind::None) {
                cells.insert(place.cell);
                if (place.kind == WordPlace::Kind::Double)
                    cells.insert(place.cell + 1);
            }
            break;
        default:
            break;
        }
    }
    for (Cell c : cells)
        if (!isInputCell(c)) {
            Word word = state(cellWidth(c), powerOnValue(c));
            if (cellWidth(c) == 1)
                word.bits.push_back(kFalse);
            unit.current[c] = word;
        }
    unit.edges.resize(unit.image->edges);
    for (auto& edge : unit.edges) {
        edge.seen = state(1, 0).bits[0];
        edge.last = state(1, 0).bits[0];
    }
    // A timer's counter, in ticks of the cycle, stops where no preset it can
    // have is still ahead of it: comparing it with the preset then answers
    // as the engine's milliseconds do.
    unit.timers.resize(unit.image->timers);
    for (const auto& in : unit.image->code) {
        if (in.op != Op::Timer || in.slot >= unit.timers.size())
            continue;
        std::int64_t presetMs = 0;
        if (in.flags & compiler::ConstantOperand)
            presetMs = 10 * std::int64_t{in.constant};
        else
            presetMs = 10 * (wordPlace(in.operand).kind == WordPlace::Kind::Register
                                 ? std::int64_t{32767}
                                 : std::int64_t{2147483647});
        auto& timer = unit.timers[in.slot];
        timer.cap = std::max(timer.cap,
                             std::max<std::int64_t>(0, (presetMs + m.m_cycleMs - 1) / m.m_cycleMs));
        timer.used = true;
    }
    for (auto& timer : unit.timers) {
        int width = 2;
        while ((std::int64_t{1} << (width - 1)) <= timer.cap)
            ++width;
        timer.ticks = state(width, 0);
        timer.lastInput = state(1, 0).bits[0];
        timer.running = state(1, 0).bits[0];
        timer.ranLast = state(1, 0).bits[0];
        if (timer.used) {
            Word ticks = timer.ticks;
            m.m_timerCounters.emplace_back(ticks, timer.cap);
            m.m_invariants.push_back(negate(w.less(w.constant(timer.cap), ticks))); // ticks <= cap
            m.m_invariants.push_back(negate(w.less(ticks, w.constant(0))));
        }
    }
    for (std::size_t i = 0; i < unit.image->steps.size(); ++i) {
        const auto& step = unit.image->steps[i];
        auto& sequence = unit.sequences[step.sequence];
        sequence.steps.push_back(step.step);
        sequence.stepCode.push_back(i);
    }
    for (auto& [number, sequence] : unit.sequences) {
        const bool single = sequence.steps.size() == 1 && sequence.steps.front() == 0;
        sequence.active = single ? w.constant(0, kStepWidth) : state(kStepWidth, 0);
        sequence.stepNew = state(1, 1).bits[0];
        sequence.resetRequested = state(1, 0).bits[0];
        if (!single) {
            Lit valid = kFalse;
            for (int step : sequence.steps)
                valid = g.disj(valid, w.equal(sequence.active, w.constant(step, kStepWidth)));
            m.m_invariants.push_back(valid);
        }
    }
}

Lit ScanBuilder::timer(ScanModel::Unit& unit, const compiler::Instruction& in, Lit guard,
                       Lit input) {
    auto& t = unit.timersNow[in.slot];
    const Cell freezeCell = cell(Area::SystemMemory, sim::engine::kTimerFreeze);
    const Lit freeze = readCell(unit, freezeCell).bits[0];
    write(unit, freezeCell, guard, w.constant(0, 2));
    // A timer whose line did not run in the previous scan starts afresh.
    const Lit fresh = negate(unit.timers[in.slot].ranLast);
    const Word zero = w.constant(0, t.ticks.width());
    const Word ticks0 = w.choose(fresh, zero, t.ticks);
    const Lit lastInput = g.conj(negate(fresh), t.lastInput);
    const Lit running0 = g.conj(negate(fresh), t.running);
    const Lit rising = g.conj(input, negate(lastInput));
    const Lit falling = g.conj(negate(input), lastInput);
    // elapsed + dt, stopped at the cap
    const Word plus = w.add(ticks0, w.bit(negate(freeze)));
    const Word advanced = w.extended(
        w.choose(w.less(w.constant(t.cap), plus), w.constant(t.cap), plus), t.ticks.width());
    auto expired = [&](const Word& ticks) {
        if (in.flags & compiler::ConstantOperand) {
            const std::int64_t presetMs = 10 * std::int64_t{in.constant};
            const std::int64_t threshold =
                presetMs <= 0 ? 0 : (presetMs + m.m_cycleMs - 1) / m.m_cycleMs;
            return negate(w.less(ticks, w.constant(threshold)));
        }
        const Word elapsedMs = w.multiply(ticks, w.constant(m.m_cycleMs));
        const Word presetMs = w.multiply(readWord(unit, in.operand), w.constant(10));
        return negate(w.less(elapsedMs, presetMs));
    };
    Word ticks;
    Lit running = kFalse;
    Lit output = kFalse;
    switch (in.aux) {
    case 0: // on-delay
        ticks = w.choose(input, w.choose(rising, zero, advanced), zero);
        output = g.conj(input, expired(ticks));
        break;
    case 1: { // pulse
        const Lit counting = g.conj(negate(rising), g.conj(input, running0));
        ticks = w.choose(rising, zero, w.choose(counting, advanced, ticks0));
        const Lit started = g.disj(rising, running0);
        running = g.conj(started, g.conj(input, negate(expired(ticks))));
        output = g.conj(input, running);
        break;
    }
    default: { // off-delay
        const Lit counting = g.conj(negate(input), running0);
        const Word counted = w.choose(falling, zero, advanced);
        ticks = w.choose(input, zero, w.choose(counting, counted, ticks0));
        running = g.disj(input, g.conj(counting, negate(expired(counted))));
        output = running;
        break;
    }
    }
    t.ticks = w.extended(w.choose(guard, ticks, t.ticks), t.ticks.width());
    t.running = g.choose(guard, running, t.running);
    t.lastInput = g.choose(guard, input, t.lastInput);
    t.ranLast = g.disj(guard, t.ranLast); // set to the guard at the end of the scan
    return (in.flags & compiler::Negated) ? g.conj(input, negate(output)) : output;
}

void ScanBuilder::arithmetic(ScanModel::Unit& unit, const compiler::Instruction& in, Lit guard,
                             const Word& a, const Word& b) {
    const WordPlace place = wordPlace(in.operand);
    const bool wide = place.kind != WordPlace::Kind::Register;
    const sim::engine::Bounds bounds =
        wide ? sim::engine::kDoubleRegisterBounds : sim::engine::kRegisterBounds;
    const Word current = readWord(unit, in.operand);
    const sim::engine::ArithmeticForm form =
        sim::engine::arithmeticForm(static_cast<compiler::ArithOp>(in.aux));
    auto scaled = [&](const Word& value, int factor) {
        return factor == 0 ? w.constant(0, 1) : factor == 1 ? value : w.negated(value);
    };
    const Word x = w.add(scaled(current, form.fromCurrent), scaled(a, form.fromA));
    const Word y = w.add(w.add(w.constant(form.constant), scaled(a, form.yA)), scaled(b, form.yB));
    const Cell overflow = cell(Area::SystemMemory, sim::engine::kOverflow);
    Word result;
    if (form.operation == sim::engine::ArithmeticForm::Operation::Divide) {
        const Lit byZero = w.isZero(y);
        write(unit, cell(Area::SystemMemory, sim::engine::kDivByZero), guard, w.bit(byZero));
        Word quotient;
        Word remainder;
        // The divisor never 0 inside: 1 stands for it and the result is chosen away.
        w.divide(x, w.choose(byZero, w.constant(1), y), quotient, remainder);
        write(unit, cell(Area::SystemRegister, sim::engine::kRemain), g.conj(guard, negate(byZero)),
              w.extended(remainder, 32));
        result = w.choose(byZero, w.constant(0), quotient);
    } else {
        result = form.operation == sim::engine::ArithmeticForm::Operation::Multiply
                     ? w.multiply(x, y)
                     : w.add(x, y);
    }
    const Lit outside =
        g.disj(w.less(result, w.constant(bounds.low)), w.less(w.constant(bounds.high), result));
    write(unit, overflow, guard, w.bit(outside));
    writeWord(unit, in.operand, guard,
              w.saturated(result, bounds.low, bounds.high, wide ? 32 : 16));
}

void ScanBuilder::runStep(ScanModel::Unit& unit, std::size_t stepCode, Lit guard, Lit& jumped,
                          Word& target) {
    const compiler::StepCode& step = unit.image->steps[stepCode];
    struct Branch {
        Lit in;
        Lit any;
    };
    std::vector<Branch> branches;
    Lit power = kTrue;
    Word a = w.constant(0, 1);
    Word b = w.constant(0, 1);
    const Cell ditto = cell(Area::SystemMemory, sim::engine::kDitto);
    for (std::uint32_t i = step.first; i < step.first + step.count && i < unit.image->code.size();
         ++i) {
        const compiler::Instruction& in = unit.image->code[i];
        const bool negated = in.flags & compiler::Negated;
        switch (in.op) {
        case Op::Rung:
            power = kTrue;
            break;
        case Op::Contact:
            power = g.conj(power, readBit(unit, in.operand) ^ (negated ? 1u : 0u));
            break;
        case Op::Edge: {
            if (in.slot >= unit.edgesNow.size())
                break;
            auto& edge = unit.edgesNow[in.slot];
            const Lit value =
                readBit(unit, in.operand) ^ ((in.flags & compiler::OperandNegated) ? 1u : 0u);
            const Lit changed = g.exclusive(value, edge.last);
            const Lit seen = g.conj(
                edge.seen, g.conj(changed, (in.flags & compiler::Rising) ? value : edge.last));
            edge.seen = g.disj(guard, edge.seen);
            edge.last = g.choose(guard, value, edge.last);
            power = g.conj(power, seen ^ (negated ? 1u : 0u));
            break;
        }
        case Op::Timer:
            if (in.slot < unit.timersNow.size())
                power = timer(unit, in, guard, power);
            break;
        case Op::LoadA:
        case Op::LoadB: {
            const Word value = (in.flags & compiler::ConstantOperand) ? w.constant(in.constant)
                                                                      : readWord(unit, in.operand);
            (in.op == Op::LoadA ? a : b) = value;
            break;
        }
        case Op::Compare: {
            Lit holds = kFalse;
            switch (static_cast<lang::CompareOp>(in.aux)) {
            case lang::CompareOp::Equal:
                holds = w.equal(a, b);
                break;
            case lang::CompareOp::Greater:
                holds = w.less(b, a);
                break;
            case lang::CompareOp::Less:
                holds = w.less(a, b);
                break;
            case lang::CompareOp::GreaterEqual:
                holds = negate(w.less(a, b));
                break;
            case lang::CompareOp::LessEqual:
                holds = negate(w.less(b, a));
                break;
            }
            power = g.conj(power, holds ^ (negated ? 1u : 0u));
            break;
        }
        case Op::BranchOpen:
            branches.push_back({power, kFalse});
            break;
        case Op::BranchNext:
            if (!branches.empty()) {
                branches.back().any = g.disj(branches.back().any, power);
                power = branches.back().in;
            }
            break;
        case Op::BranchClose:
            if (!branches.empty()) {
                power = g.disj(power, branches.back().any);
                branches.pop_back();
            }
            break;
        case Op::Coil:
            writeBit(unit, in.operand, guard, power);
            write(unit, ditto, guard, w.bit(power));
            break;
        case Op::Set:
            writeBit(unit, in.operand, g.conj(guard, power), kTrue);
            write(unit, ditto, guard, w.bit(power));
            break;
        case Op::Reset:
            writeBit(unit, in.operand, g.conj(guard, power), kFalse);
            write(unit, ditto, guard, w.bit(power));
            break;
        case Op::Toggle:
            writeBit(unit, in.operand, g.conj(guard, power),
                     negate(readOutputBit(unit, in.operand)));
            write(unit, ditto, guard, w.bit(power));
            break;
        case Op::Jump: {
            const Lit taken = g.conj(guard, power);
            jumped = g.disj(jumped, taken);
            target =
                w.extended(w.choose(taken, w.constant(in.slot, kStepWidth), target), kStepWidth);
            break;
        }
        case Op::SequenceReset:
            if (in.slot < 10)
                if (auto at = unit.sequences.find(in.slot); at != unit.sequences.end())
                    at->second.resetNow = g.disj(at->second.resetNow, g.conj(guard, power));
            break;
        case Op::Arith:
            arithmetic(unit, in, g.conj(guard, power), a, b);
            break;
        case Op::System: {
            // What a system block computes is left free: each output it
            // writes may take any value, every scan its step runs. Proofs
            // stay sound; a counterexample must be one the simulator repeats.
            const compiler::SystemInstruction* system = compiler::findSystemInstruction(in.aux);
            abstracted(unit, in,
                       "the outputs of " +
                           (system ? std::string(system->name) : std::to_string(in.aux)));
            for (std::uint32_t k = 1; k <= in.slot && i + k < step.first + step.count; ++k) {
                const compiler::Instruction& argument = unit.image->code[i + k];
                if (argument.op != Op::Argument || !(argument.aux & compiler::ArgumentWritten) ||
                    (argument.flags & compiler::ConstantOperand))
                    continue;
                if (argument.aux & compiler::ArgumentWord)
                    writeWord(unit, argument.operand, guard, freeWord(argument.operand));
                else
                    writeBit(unit, argument.operand, guard, freeWord({}).bits[0]);
            }
            power = kTrue;
            break;
        }
        case Op::Argument:
            break;
        }
    }
}

// The coils of a step that is left go off (engine::UnitState::leaveStep).
void ScanBuilder::leaveStep(ScanModel::Unit& unit, std::size_t stepCode, Lit guard) {
    const compiler::StepCode& step = unit.image->steps[stepCode];
    for (std::uint32_t i = step.first; i < step.first + step.count && i < unit.image->code.size();
         ++i)
        if (const auto& in = unit.image->code[i];
            in.op == Op::Coil || (in.op == Op::Argument && in.aux == compiler::ArgumentWritten &&
                                  !(in.flags & compiler::ConstantOperand)))
            writeBit(unit, in.operand, guard, kFalse);
}

void ScanBuilder::scan(ScanModel::Unit& unit) {
    unit.edgesNow = unit.edges;
    unit.timersNow = unit.timers;
    for (auto& timer : unit.timersNow)
        timer.ranLast = kFalse; // becomes "ran in this scan"
    for (auto& [number, sequence] : unit.sequences) {
        sequence.activeNow = sequence.active;
        sequence.stepNewNow = sequence.stepNew;
        sequence.resetNow = sequence.resetRequested;
    }
    // What the simulator sets before the programs run (UnitEngine::scan).
    write(unit, cell(Area::SystemMemory, kSysInit), kTrue, w.bit(m.m_firstScan));
    for (int memory : kFlashMemories) {
        const int period = memory == 2 || memory == 3 ? 1000
                           : memory == 4              ? 100
                           : memory == 5              ? 500
                                                      : 1090;
        const Word& t = m.m_timeOfDay.at(period);
        auto below = [&](std::int64_t ms) {
            return w.less(t, w.constant(ms));
        };
        Lit on = kFalse;
        switch (memory) {
        case 2:
            on = below(400);
            break;
        case 3:
            on = below(500);
            break;
        case 4:
            on = below(50);
            break;
        case 5:
            on = below(170);
            break;
        default:
            on = g.disj(below(110), g.conj(negate(below(310)), below(420)));
            break;
        }
        write(unit, cell(Area::SystemMemory, memory), kTrue, w.bit(on));
    }
    for (int station = 0; station < 32; ++station)
        write(unit, cell(Area::SystemMemory, 100 + station), kTrue,
              w.bit(literalOf(unitAt(station) != nullptr)));
    for (auto& [number, sequence] : unit.sequences) {
        const Lit held = sequence.resetNow;
        sequence.resetNow = kFalse;
        const Lit leaving = g.conj(held, negate(w.equal(sequence.activeNow, w.constant(0))));
        for (std::size_t s = 0; s < sequence.steps.size(); ++s)
            leaveStep(unit, sequence.stepCode[s],
                      g.conj(leaving, w.equal(sequence.activeNow,
                                              w.constant(sequence.steps[s], kStepWidth))));
        sequence.activeNow = w.extended(
            w.choose(leaving, w.constant(0, kStepWidth), sequence.activeNow), kStepWidth);
        sequence.stepNewNow = g.disj(leaving, sequence.stepNewNow);
        write(unit, cell(Area::SystemMemory, kStepNew), kTrue, w.bit(sequence.stepNewNow));
        sequence.stepNewNow = kFalse;
        Lit jumped = kFalse;
        Word target = w.constant(0, kStepWidth);
        std::vector<Lit> running;
        for (std::size_t s = 0; s < sequence.steps.size(); ++s)
            running.push_back(
                w.equal(sequence.activeNow, w.constant(sequence.steps[s], kStepWidth)));
        for (std::size_t s = 0; s < sequence.steps.size(); ++s)
            runStep(unit, sequence.stepCode[s], running[s], jumped, target);
        const Lit moves = g.conj(jumped, negate(held));
        for (std::size_t s = 0; s < sequence.steps.size(); ++s)
            leaveStep(unit, sequence.stepCode[s], g.conj(moves, running[s]));
        sequence.activeNow = w.extended(w.choose(moves, target, sequence.activeNow), kStepWidth);
        sequence.stepNewNow = g.disj(moves, sequence.stepNewNow);
    }
}

void ScanBuilder::finish() {
    for (auto& unit : m.m_units) {
        for (const auto& [c, word] : unit->current)
            m.setNext(word, readCell(*unit, c));
        for (std::size_t i = 0; i < unit->edges.size(); ++i) {
            m.setNext(w.bit(unit->edges[i].seen), w.bit(unit->edgesNow[i].seen));
            m.setNext(w.bit(unit->edges[i].last), w.bit(unit->edgesNow[i].last));
        }
        for (std::size_t i = 0; i < unit->timers.size(); ++i) {
            const auto& before = unit->timers[i];
            const auto& after = unit->timersNow[i];
            m.setNext(before.ticks, after.ticks);
            m.setNext(w.bit(before.lastInput), w.bit(after.lastInput));
            m.setNext(w.bit(before.running), w.bit(after.running));
            m.setNext(w.bit(before.ranLast), w.bit(after.ranLast));
        }
        for (auto& [number, sequence] : unit->sequences) {
            if (sequence.active.bits.size() && g.isVariable(nodeOf(sequence.active.bits[0])))
                m.setNext(sequence.active, sequence.activeNow);
            m.setNext(w.bit(sequence.stepNew), w.bit(sequence.stepNewNow));
            m.setNext(w.bit(sequence.resetRequested), w.bit(sequence.resetNow));
        }
    }
    // The bus after the scan: inputs as this scan had them, and with a CAN
    // bus cycle time, the end of this scan when its time came round.
    for (auto& unit : m.m_units) {
        for (const auto& [c, word] : unit->previousInput)
            m.setNext(word, inputWord(*unit, c));
        for (const auto& [c, word] : unit->published)
            m.setNext(word, w.choose(unit->publishes, readCell(*unit, c), word));
    }
}

ScanModel::ScanModel(const std::vector<compiler::UnitImage>& images, int cycleMs)
    : m_cycleMs(cycleMs) {
    for (const auto& image : images) {
        auto unit = std::make_unique<Unit>();
        unit->image = &image;
        unit->station = image.station;
        // A safe input slave's input follows its two channels through the
        // channel monitoring; the model takes it, and SR_ASi_Slave_Chanf,
        // as inputs of their own.
        for (const auto& slave : image.asi.slaves)
            if (project::hasChannels(static_cast<project::AsiSlaveType>(slave.type)) && !slave.b) {
                unit->monitoredChannels = true;
                m_abstractions.push_back("unit " + std::to_string(image.station) +
                                         ": the channel monitoring of AS-i safe input slave " +
                                         std::to_string(slave.number));
            }
        m_units.push_back(std::move(unit));
    }
    std::sort(m_units.begin(), m_units.end(),
              [](const auto& a, const auto& b) { return a->station < b->station; });
    buildScan();
}

ScanModel::~ScanModel() = default;

void ScanModel::buildScan() {
    ScanBuilder builder(*this);
    // Virtual time: whether this is the first scan, and the time of the
    // scan's start modulo each flashing memory's period.
    const Word started = addState(1, 0);
    m_firstScan = negate(started.bits[0]);
    setNext(started, m_words.constant(-1, 1));
    for (int period : {1000, 100, 500, 1090}) {
        int width = 2;
        while ((1 << (width - 1)) <= period)
            ++width;
        const Word t = addState(width, 0);
        const Word plus = m_words.add(t, m_words.constant(m_cycleMs % period));
        const Word wrapped = m_words.subtract(plus, m_words.constant(period));
        setNext(t, m_words.extended(
                       m_words.choose(m_words.less(plus, m_words.constant(period)), plus, wrapped),
                       width));
        m_timeOfDay[period] = t;
        m_invariants.push_back(m_words.less(t, m_words.constant(period)));
        m_invariants.push_back(negate(m_words.less(t, m_words.constant(0))));
    }
    for (auto& unit : m_units) {
        builder.prepare(*unit);
        if (const int cycle = unit->image->canCycleMs) {
            // Publishes at the first scan end at or past each multiple of the
            // CAN cycle: when this scan's time interval crosses one.
            int width = 2;
            while ((1 << (width - 1)) <= cycle)
                ++width;
            const Word r = addState(width, 0);
            const Word plus = m_words.add(r, m_words.constant(m_cycleMs));
            unit->publishes = negate(m_words.less(plus, m_words.constant(cycle)));
            Word wrapped = plus;
            // Several multiples in one scan: the remainder is what matters.
            Word quotientUnused;
            Word remainder;
            m_words.divide(plus, m_words.constant(cycle), quotientUnused, remainder);
            wrapped = remainder;
            setNext(r, m_words.extended(wrapped, width));
        }
    }
    for (auto& unit : m_units)
        builder.scan(*unit);
    builder.finish();
}

Word ScanModel::addState(int width, std::int64_t initial) {
    Word word = m_words.variables(width);
    m_stateWords.push_back(word);
    m_stateOfNode.resize(m_graph.nodes(), -1);
    for (int i = 0; i < width; ++i) {
        m_stateOfNode[nodeOf(word.bits[static_cast<std::size_t>(i)])] =
            static_cast<std::int32_t>(m_state.size());
        m_state.push_back({word.bits[static_cast<std::size_t>(i)], kFalse,
                           ((initial >> std::min(i, 63)) & 1) != 0});
    }
    return word;
}

void ScanModel::setNext(const Word& current, const Word& next) {
    const Word extended = m_words.extended(next, current.width());
    for (int i = 0; i < current.width(); ++i) {
        const Lit bit = current.bits[static_cast<std::size_t>(i)];
        if (const int state = stateOf(nodeOf(bit)); state >= 0)
            m_state[static_cast<std::size_t>(state)].next =
                extended.bits[static_cast<std::size_t>(i)];
    }
}

Word ScanModel::valueAfterScan(const lang::Address& address) {
    Unit* unit = nullptr;
    for (auto& u : m_units)
        if (u->station == address.unit)
            unit = u.get();
    if (!unit)
        return m_words.constant(0, 1);
    if (address.kind == AddressKind::Sequence) {
        auto at = unit->sequences.find(address.index);
        if (at == unit->sequences.end() || address.index < 0 || address.index > 9)
            return m_words.constant(-1);
        return at->second.activeNow;
    }
    ScanBuilder builder(*this);
    if (sim::readsAsNumber(address.kind))
        return builder.readWord(*unit, address);
    return m_words.bit(builder.readBit(*unit, address));
}

int ScanModel::stateOf(std::uint32_t node) const {
    return node < m_stateOfNode.size() ? m_stateOfNode[node] : -1;
}

std::vector<std::uint32_t> ScanModel::cone(const std::vector<Lit>& roots) const {
    std::vector<bool> seen(m_graph.nodes(), false);
    std::vector<std::uint32_t> stack{0};
    for (Lit root : roots)
        stack.push_back(nodeOf(root));
    std::vector<std::uint32_t> nodes;
    while (!stack.empty()) {
        const std::uint32_t node = stack.back();
        stack.pop_back();
        if (seen[node])
            continue;
        seen[node] = true;
        nodes.push_back(node);
        if (node == 0)
            continue;
        if (m_graph.isVariable(node)) {
            if (const int state = stateOf(node); state >= 0)
                stack.push_back(nodeOf(m_state[static_cast<std::size_t>(state)].next));
            continue;
        }
        stack.push_back(nodeOf(m_graph.left(node)));
        stack.push_back(nodeOf(m_graph.right(node)));
    }
    return nodes;
}

std::optional<ScanModel::TimerState> ScanModel::timerState(int station, int slot) const {
    for (const auto& unit : m_units)
        if (unit->station == station && slot >= 0 &&
            static_cast<std::size_t>(slot) < unit->timersNow.size()) {
            const auto& t = unit->timersNow[static_cast<std::size_t>(slot)];
            return TimerState{t.ticks, t.lastInput, t.running, t.ranLast, t.cap};
        }
    return std::nullopt;
}

} // namespace rs::prove
