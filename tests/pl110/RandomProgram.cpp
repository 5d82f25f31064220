// SPDX-License-Identifier: GPL-3.0-or-later
#include "RandomProgram.h"

#include <map>
#include <set>

namespace rs::pl110::testing {

namespace {

class Generator {
public:
    Generator(std::mt19937& random, bool runnable) : m_random(random), m_runnable(runnable) {}

    Program program() {
        Program program;
        if (chance(2))
            program.name = pick({"Conveyor", "Press line; cell 2", "Mixer  tank", "Ventilation"});
        const int names = between(0, 6);
        for (int i = 0; i < names; ++i)
            declare(program);
        program.declarations.push_back(blankOrComment());
        const int init = between(0, 3);
        for (int i = 0; i < init; ++i)
            program.init.push_back(line());
        const int main = between(1, 14);
        for (int i = 0; i < main; ++i)
            program.main.push_back(line());
        return program;
    }

private:
    int between(int low, int high) {
        return std::uniform_int_distribution<int>(low, high)(m_random);
    }
    bool chance(int oneIn) { return between(1, oneIn) == 1; }
    template <class T> T pick(std::initializer_list<T> items) {
        return *(items.begin() + between(0, static_cast<int>(items.size()) - 1));
    }
    std::string pick(std::initializer_list<const char*> items) {
        return *(items.begin() + between(0, static_cast<int>(items.size()) - 1));
    }

    Address numbered(Area area, Width width = Width::Bit) {
        const AreaInfo& info = areaInfo(area);
        const int last = info.last - (width == Width::Double ? 1 : 0);
        return {area, width, between(info.first, last),
                info.bitsOfWords && width == Width::Bit ? between(0, 15) : -1};
    }

    Address bitAddress() {
        return numbered(pick({Area::Input, Area::Output, Area::Marker, Area::Bistable, Area::Timer,
                              Area::Counter, Area::Variable, Area::SpecialMarker}));
    }

    Address wordAddress() {
        if (chance(6))
            return numbered(pick({Area::Variable, Area::SpecialMarker}), Width::Double);
        const Area area = pick({Area::Variable, Area::SpecialMarker, Area::AnalogInput,
                                Area::AnalogOutput, Area::Timer, Area::Counter, Area::TimerPreset,
                                Area::CounterPreset, Area::Eeprom});
        Address address = numbered(area, Width::Word);
        if (area == Area::Timer || area == Area::Counter)
            address.width = Width::Word;
        return address;
    }

    Address writableWord() {
        for (;;) {
            Address address = wordAddress();
            if (areaInfo(address.area).programWrites && address.area != Area::SpecialMarker)
                return address;
        }
    }

    Operand operand(Address address, bool wordWanted) {
        Operand operand;
        operand.address = address;
        // A name stands for the address it was declared for.
        for (const auto& [name, declared] : m_names)
            if ((wordWanted ? asWord(declared) : declared) == address && chance(2)) {
                operand.name = name;
                break;
            }
        return operand;
    }

    Value value(bool wordOnly = false) {
        Value value;
        if (chance(2)) {
            value.constant = wordOnly || chance(2) ? between(kWordMin, kWordMax)
                                                   : static_cast<std::int32_t>(m_random());
            return value;
        }
        Address address = wordOnly ? numbered(Area::Variable, Width::Word) : wordAddress();
        value.operand = operand(address, true);
        return value;
    }

    void declare(Program& program) {
        static const char* const kNames[] = {"Start", "Stop",   "Motor",     "Level", "Count",
                                             "Delay", "Pump_2", "Tank.High", "Fläkt", "Door"};
        const std::string name = kNames[between(0, 9)];
        if (m_names.contains(name))
            return;
        // As reading gives it: a timer's or counter's name is declared for the number.
        const Address address =
            readAddress(toString(chance(2) ? bitAddress() : wordAddress())).address;
        for (const auto& [other, declared] : m_names)
            if (declared == address)
                return;
        m_names[name] = address;
        Line line;
        NameDeclaration declaration;
        declaration.variable.address = address;
        declaration.name = name;
        line.body = declaration;
        if (chance(2))
            line.comment = " " + pick({"push button", "K1; main contactor", "ms", "x"});
        program.declarations.push_back(line);
    }

    Line blankOrComment() {
        Line line;
        if (chance(2))
            line.body = CommentLine{pick({" Safety door", "", "--- section ---", " a ; b"})};
        return line;
    }

    Circuit element() {
        Element element;
        const int kind = between(0, 9);
        if (kind < 5) {
            element.kind = kind < 3 ? ElementKind::NormallyOpen : ElementKind::NormallyClosed;
            element.operand = operand(bitAddress(), false);
        } else if (kind < 7) {
            element.kind = ElementKind::Compare;
            element.left = value();
            element.compare =
                pick({CompareOp::Equal, CompareOp::NotEqual, CompareOp::Greater, CompareOp::Less,
                      CompareOp::GreaterEqual, CompareOp::LessEqual});
            element.right = value();
        } else {
            element.kind =
                pick({ElementKind::Not, ElementKind::RisingEdge, ElementKind::FallingEdge});
        }
        return Circuit::of(element);
    }

    Circuit circuit(int depth) {
        if (depth > 3 || chance(3))
            return element();
        std::vector<Circuit> parts;
        const int count = between(2, 4);
        for (int i = 0; i < count; ++i)
            parts.push_back(circuit(depth + 1));
        return chance(2) ? Circuit::series(std::move(parts)) : Circuit::parallel(std::move(parts));
    }

    Output output() {
        Output out;
        switch (between(0, 6)) {
        case 0:
            out.kind = OutputKind::Coil;
            out.target =
                operand(numbered(pick({Area::Output, Area::Marker, Area::Bistable})), false);
            break;
        case 1:
            out.kind = pick({OutputKind::SetBit, OutputKind::ResetBit});
            out.target = operand(numbered(Area::Variable), false);
            break;
        case 2: {
            out.kind = OutputKind::Timer;
            out.timer = pick({TimerType::OnDelay, TimerType::OffDelay, TimerType::Retentive});
            out.base = pick({TimeBase::Ms10, TimeBase::Ms100, TimeBase::S1});
            Address timer = numbered(Area::Timer);
            if (m_runnable) {
                if (m_timers.size() == 48)
                    return output();
                while (m_timers.contains(timer.number))
                    timer = numbered(Area::Timer);
                m_timers.insert(timer.number);
            }
            out.target = operand(timer, false);
            out.preset = m_runnable ? Value{{}, between(0, 300), {}} : value();
            break;
        }
        case 3: {
            out.kind = OutputKind::Counter;
            out.input = pick({CounterInput::Up, CounterInput::Down, CounterInput::Reset});
            const Address counter = numbered(Area::Counter);
            out.target = operand(counter, false);
            if (m_runnable) {
                const auto [known, fresh] = m_counters.try_emplace(
                    counter.number,
                    std::pair{pick({CounterType::Up, CounterType::Down}), between(0, 20)});
                out.counter = known->second.first;
                out.preset = Value{{}, known->second.second, {}};
            } else {
                out.counter = pick({CounterType::Up, CounterType::Down});
                out.preset = value();
            }
            break;
        }
        case 4:
        case 5:
            out.kind = OutputKind::Move;
            out.target = operand(m_runnable ? writableWord() : wordAddress(), true);
            out.left = value(m_runnable && out.target.address.width != Width::Double);
            break;
        default:
            out.kind = OutputKind::Formula;
            out.target = operand(m_runnable ? writableWord() : wordAddress(), true);
            out.left = value();
            out.formula =
                pick({FormulaOp::Add, FormulaOp::Sub, FormulaOp::Mul, FormulaOp::Div, FormulaOp::Or,
                      FormulaOp::And, FormulaOp::Xor, FormulaOp::ShiftLeft, FormulaOp::ShiftRight});
            out.right = value();
            break;
        }
        return out;
    }

    Line line() {
        if (chance(6))
            return blankOrComment();
        Line line;
        Rung rung;
        if (!chance(5))
            rung.condition = circuit(0);
        rung.output = output();
        line.body = std::move(rung);
        if (chance(4))
            line.comment = pick({" start the pump", ";;", " ", "Å ä ö ß"});
        if (line.comment && line.comment == " ")
            line.comment = "";
        return line;
    }

    std::mt19937& m_random;
    bool m_runnable;
    std::map<std::string, Address> m_names;
    std::set<int> m_timers;
    std::map<int, std::pair<CounterType, int>> m_counters;
};

} // namespace

Program randomProgram(std::mt19937& random, bool runnable) {
    return Generator(random, runnable).program();
}

} // namespace rs::pl110::testing
