// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProgramCheck.h"

#include <map>

namespace rs::pl110 {

namespace {

class Checker {
public:
    explicit Checker(lang::Diagnostics& diagnostics) : m_diagnostics(diagnostics) {}

    void lines(const std::vector<Line>& lines) {
        for (const Line& line : lines)
            if (const auto* rung = std::get_if<Rung>(&line.body))
                check(*rung, line.location.line);
    }

private:
    void error(const lang::SourceLocation& at, std::string message) {
        m_diagnostics.push_back({lang::Severity::Error, at.line, at.column, std::move(message)});
    }

    static bool isBit(const Address& address) { return address.width == Width::Bit; }

    void contact(const Operand& operand) {
        if (!isBit(operand.address))
            error(operand.location,
                  toString(operand.address) +
                      " is a word: a contact reads a bit (BIT contact: V1.0-V1.15)");
    }

    void word(const Value& value, bool doubleAllowed = true) {
        if (value.isConstant())
            return;
        const Address& address = value.operand->address;
        if (isBit(address))
            error(value.operand->location,
                  toString(address) + " is a bit: a word is wanted here (VW, SMW, AI, T, C, ...)");
        else if (!doubleAllowed && address.width == Width::Double)
            error(value.operand->location,
                  toString(address) + " is a double word: a word is wanted");
    }

    void writableWord(const Operand& target) {
        const Address& address = target.address;
        if (isBit(address)) {
            error(target.location,
                  toString(address) +
                      " is a bit: MOV and FM write a word; SBIT and RBIT write bits");
            return;
        }
        if (!areaInfo(address.area).programWrites || isReadOnlySpecial(address))
            error(target.location, toString(address) + " is read only");
    }

    void fits(const Value& value, const Address& target, const char* what) {
        if (!value.isConstant())
            return;
        if (target.width != Width::Double &&
            (value.constant < kWordMin || value.constant > kWordMax))
            error(value.location, std::string(what) + " " + std::to_string(value.constant) +
                                      " does not fit a word: -32768-32767");
    }

    void presetSource(const Value& preset, std::int32_t lowest) {
        if (preset.isConstant()) {
            if (preset.constant < lowest || preset.constant > kWordMax)
                error(preset.location,
                      "the preset is out of range: " + std::to_string(lowest) + "-32767");
            return;
        }
        const Area area = preset.operand->address.area;
        if (preset.operand->address.width != Width::Word ||
            (area != Area::Variable && area != Area::SpecialMarker && area != Area::AnalogInput))
            error(preset.operand->location,
                  "a preset is a constant or a word of VW, SMW or AI, not " +
                      toString(preset.operand->address));
    }

    void circuit(const Circuit& circuit) {
        if (!circuit.isElement()) {
            for (const Circuit& part : circuit.parts)
                this->circuit(part);
            return;
        }
        const Element& element = circuit.element;
        switch (element.kind) {
        case ElementKind::NormallyOpen:
        case ElementKind::NormallyClosed:
            contact(element.operand);
            break;
        case ElementKind::Compare:
            word(element.left);
            word(element.right);
            break;
        case ElementKind::Not:
        case ElementKind::RisingEdge:
        case ElementKind::FallingEdge:
            break;
        }
    }

    void check(const Rung& rung, int line) {
        if (rung.condition)
            circuit(*rung.condition);
        const Output& out = rung.output;
        const Address& target = out.target.address;
        switch (out.kind) {
        case OutputKind::Coil:
            if (target.width != Width::Bit || target.bit >= 0 ||
                (target.area != Area::Output && target.area != Area::Marker &&
                 target.area != Area::Bistable))
                error(out.target.location,
                      "a coil writes Q, M or B, not " + toString(target) +
                          (target.bit >= 0 ? ": SBIT and RBIT write bits of words" : ""));
            break;
        case OutputKind::SetBit:
        case OutputKind::ResetBit:
            if (target.bit < 0)
                error(out.target.location,
                      "SBIT and RBIT write a bit of a V or SM word (V3.4), not " +
                          toString(target));
            else if (isReadOnlySpecial(target))
                error(out.target.location, toString(target) + " is read only");
            break;
        case OutputKind::Timer: {
            if (target.area != Area::Timer)
                error(out.target.location,
                      "a timer coil names a timer T1-T48, not " + toString(target));
            presetSource(out.preset, 0);
            const auto [at, fresh] = m_timers.try_emplace(target.number, line);
            if (!fresh && target.area == Area::Timer)
                error(out.target.location, "T" + std::to_string(target.number) +
                                               " already has its coil on line " +
                                               std::to_string(at->second));
            break;
        }
        case OutputKind::Counter: {
            if (target.area != Area::Counter) {
                error(out.target.location,
                      "a counter coil names a counter C1-C16, not " + toString(target));
                break;
            }
            presetSource(out.preset, kWordMin);
            const auto [at, fresh] = m_counters.try_emplace(target.number, out);
            if (!fresh && (at->second.counter != out.counter || at->second.preset != out.preset))
                error(out.target.location,
                      "C" + std::to_string(target.number) +
                          "'s coils must agree on MUP or MDOWN and the preset");
            break;
        }
        case OutputKind::Move:
            writableWord(out.target);
            word(out.left);
            fits(out.left, target, "the constant");
            break;
        case OutputKind::Formula:
            writableWord(out.target);
            word(out.left);
            word(out.right);
            break;
        }
    }

    lang::Diagnostics& m_diagnostics;
    std::map<int, int> m_timers;      // number -> line of its coil
    std::map<int, Output> m_counters; // number -> its first coil
};

} // namespace

namespace {

// Words whose every bit the PL110 writes: the rotary switch, scan times,
// encoder counts and rates, serial status; and SM0 and SM1 as whole words,
// which hold read-only bits.
bool readOnlySpecialWord(int word) {
    switch (word) {
    case 0:
    case 1:
    case 5:
    case 6:
    case 7:
    case 8:
    case 20:
    case 21:
    case 22:
    case 23:
    case 28:
    case 29:
    case 30:
    case 31:
    case 70:
    case 80:
    case 90:
        return true;
    default:
        return false;
    }
}

} // namespace

bool isReadOnlySpecial(const Address& address) {
    if (address.area != Area::SpecialMarker)
        return false;
    const int word = address.number;
    if (address.bit >= 0) {
        if (word == 0) // first scan, the clocks, port activity
            return address.bit >= 1 && address.bit <= 8 && address.bit != 5;
        if (word == 1) // analogue inputs out of range
            return address.bit >= 12;
        return readOnlySpecialWord(word);
    }
    if (address.width == Width::Double)
        return readOnlySpecialWord(word) || readOnlySpecialWord(word + 1);
    return readOnlySpecialWord(word);
}

lang::Diagnostics checkProgram(const Program& program) {
    lang::Diagnostics diagnostics;
    Checker checker(diagnostics);
    checker.lines(program.init);
    checker.lines(program.main);
    lang::sortByPlace(diagnostics);
    return diagnostics;
}

} // namespace rs::pl110
