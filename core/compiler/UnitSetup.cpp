// SPDX-License-Identifier: GPL-3.0-or-later
#include "UnitSetup.h"

#include "lang/Keywords.h"

#include <algorithm>

namespace rs::compiler {

namespace {

using lang::AddressKind;

std::string two(int station) {
    return (station < 10 ? "0" : "") + std::to_string(station);
}

bool isPulse(const std::string& option) {
    return option == lang::kAPulseOption || option == lang::kBPulseOption ||
           option == lang::kCPulseOption;
}

std::string terminalName(const lang::Address& address) {
    return lang::toString(address);
}

class UnitCollector {
public:
    UnitCollector(const lang::Document& document, lang::Diagnostics& diagnostics)
        : m_document(document), m_diagnostics(diagnostics) {}

    UnitSetups run() {
        struct Typed {
            const lang::TypeDeclaration* declaration;
            lang::SourceLocation at;
        };
        std::map<int, Typed> types;
        auto scanDeclarations = [&](const std::vector<lang::Line>& lines) {
            for (const auto& line : lines) {
                auto* declaration = std::get_if<lang::Declaration>(&line.body);
                if (!declaration)
                    continue;
                if (auto* id = std::get_if<lang::IdDeclaration>(&declaration->body)) {
                    if (!validStation(id->station, declaration->location))
                        continue;
                    if (auto it = m_units.find(id->station); it != m_units.end()) {
                        error(declaration->location, "unit " + std::to_string(id->station) +
                                                         " is already declared at line " +
                                                         std::to_string(it->second.declared.line));
                        continue;
                    }
                    UnitSetup& unit = m_units[id->station];
                    unit.station = id->station;
                    unit.type = &target::unitTypeInfo(target::baseType(id->family));
                    unit.declared = declaration->location;
                    m_families[id->station] = id->family;
                } else if (auto* type = std::get_if<lang::TypeDeclaration>(&declaration->body)) {
                    if (!validStation(type->station, declaration->location))
                        continue;
                    if (auto it = types.find(type->station); it != types.end()) {
                        error(declaration->location, "the type of unit " +
                                                         std::to_string(type->station) +
                                                         " is already declared at line " +
                                                         std::to_string(it->second.at.line));
                        continue;
                    }
                    types[type->station] = {type, declaration->location};
                }
            }
        };
        scanDeclarations(m_document.preamble);
        for (const auto& program : m_document.units)
            scanDeclarations(program.declarations);

        for (const auto& [station, typed] : types) {
            auto unit = m_units.find(station);
            if (unit == m_units.end()) {
                error(typed.at, "type_pluto:" + two(station) +
                                    " names a unit that has no id_pluto declaration");
                continue;
            }
            const target::UnitTypeInfo* info = target::findUnitType(typed.declaration->type);
            if (!info)
                continue; // the parser has reported the unknown type
            if (info->family != m_families[station]) {
                error(typed.at, target::withArticle(*info) + " is declared with '! " +
                                    std::string(lang::idKeyword(info->family)) + ":" +
                                    two(station) + "=...', not with '! " +
                                    std::string(lang::idKeyword(m_families[station])) + "'");
            }
            unit->second.type = info;
            if (typed.declaration->instructionSet)
                unit->second.instructionSet = typed.declaration->instructionSet;
        }

        for (const auto& program : m_document.units) {
            const int station = program.station();
            const lang::SourceLocation at = program.header.location;
            if (!validStation(station, at))
                continue;
            auto unit = m_units.find(station);
            if (unit == m_units.end()) {
                error(at, "code for unit " + std::to_string(station) +
                              ", which has no '! id_pluto:" + two(station) + "=...' declaration");
                continue;
            }
            if (unit->second.program) {
                error(at, "the code of unit " + std::to_string(station) +
                              " already starts at line " +
                              std::to_string(unit->second.program->header.location.line));
                continue;
            }
            unit->second.program = &program;
            collectTerminals(unit->second, program.declarations);
        }
        return std::move(m_units);
    }

private:
    void error(lang::SourceLocation at, std::string message) {
        m_diagnostics.push_back({lang::Severity::Error, at.line, at.column, std::move(message)});
    }

    void warning(lang::SourceLocation at, std::string message) {
        m_diagnostics.push_back({lang::Severity::Warning, at.line, at.column, std::move(message)});
    }

    bool validStation(int station, lang::SourceLocation at) {
        if (station >= 0 && station <= 31)
            return true;
        error(at, "station number " + std::to_string(station) + " is outside 0-31");
        return false;
    }

    void collectTerminals(UnitSetup& unit, const std::vector<lang::Line>& lines) {
        for (const auto& line : lines) {
            auto* declaration = std::get_if<lang::Declaration>(&line.body);
            if (!declaration)
                continue;
            auto* io = std::get_if<lang::IoDeclaration>(&declaration->body);
            if (!io)
                continue;
            const lang::Address& address = io->io.address;
            const lang::SourceLocation at = io->io.location;
            if (address.unit != unit.station) {
                error(at, terminalName(address) + " belongs to unit " +
                              std::to_string(address.unit) +
                              "; declare its I/O in that unit's code");
                continue;
            }
            if (!checkOptions(unit, *io, at))
                continue;
            auto& map = address.kind == AddressKind::AnalogInput ? unit.analogTerminals
                        : address.kind == AddressKind::Output &&
                                !target::contains(unit.type->configurableTerminals, address.index)
                            ? unit.safetyOutputs
                            : unit.terminals;
            if (auto it = map.find(address.index); it != map.end()) {
                error(at, "terminal " + std::to_string(address.index) +
                              " is already declared at line " +
                              std::to_string(it->second.location.line));
                continue;
            }
            map[address.index] = {address.kind, io->options, at};
        }
    }

    // Only what the I/O Options page of the original tool lets a user choose.
    bool checkOptions(const UnitSetup& unit, const lang::IoDeclaration& io,
                      lang::SourceLocation at) {
        const target::UnitTypeInfo& type = *unit.type;
        const lang::Address& a = io.io.address;
        const std::string name = terminalName(a);
        const std::string typeName = target::withArticle(type);
        auto has = [&](std::string_view option) {
            return std::find(io.options.begin(), io.options.end(), option) != io.options.end();
        };
        std::vector<std::string> seen;
        for (const auto& option : io.options) {
            if (std::find(seen.begin(), seen.end(), option) != seen.end()) {
                error(at, name + ": option '" + option + "' is given twice");
                return false;
            }
            seen.push_back(option);
        }
        const auto pulses = std::count_if(io.options.begin(), io.options.end(), [](auto& o) {
            return isPulse(o) || o == lang::kStaticOption;
        });
        auto signalRules = [&](bool allowSwitches, bool allowCrossTalk) {
            if (pulses != 1) {
                error(at, name + " needs exactly one signal: a_pulse, b_pulse, c_pulse or static");
                return false;
            }
            for (const auto& option : io.options) {
                if (isPulse(option) || option == lang::kStaticOption)
                    continue;
                if ((option == lang::kNonInvertedOption || option == lang::kNoFilterOption) &&
                    allowSwitches) {
                    if (option == lang::kNonInvertedOption && has(lang::kStaticOption)) {
                        error(at, name + ": non_inv applies to dynamic signals (a_pulse, b_pulse, "
                                         "c_pulse), not to static");
                        return false;
                    }
                    continue;
                }
                if (option == lang::kCrossTalkOption && allowCrossTalk && !has(lang::kStaticOption))
                    continue;
                error(at, name + " cannot take the option '" + option + "'");
                return false;
            }
            return true;
        };
        switch (a.kind) {
        case AddressKind::Input:
            if (!target::contains(type.globalInputs, a.index) &&
                !target::contains(type.localInputs, a.index)) {
                error(at, typeName + " has no input " + name);
                return false;
            }
            if (!signalRules(true, target::contains(type.configurableTerminals, a.index)))
                return false;
            // The manual's footnote to I_.10..I_.17.
            if (has(lang::kStaticOption) && a.index >= 10 && a.index <= 17)
                warning(at, name + ",static does not fulfil category 4 (EN 954-1) as a stand-alone "
                                   "input");
            return true;
        case AddressKind::Output:
            if (!target::hasVariable(type, a, unit.instructionSet)) {
                error(at, typeName + " has no output " + name);
                return false;
            }
            if ((a.index == 2 || a.index == 3) && has(lang::kNoTestPulseOption)) {
                if (!type.testPulsesCanBeDisabled ||
                    !target::contains(type.globalSafetyOutputs, a.index)) {
                    error(at, "the test pulses of " + name + " cannot be disabled on " + typeName);
                    return false;
                }
                if (io.options.size() != 1) {
                    error(at, name + " takes only the option no_test_pulse");
                    return false;
                }
                return true;
            }
            if (!target::contains(type.nonSafetyOutputs, a.index)) {
                error(at, name + " takes no I/O options: only the non-failsafe outputs Q" +
                              std::to_string(a.unit) +
                              ".10.. and Q2/Q3 (no_test_pulse) are declared");
                return false;
            }
            return signalRules(false, false);
        case AddressKind::InputOutput:
            if (!target::contains(type.configurableTerminals, a.index)) {
                error(at, typeName + " has no terminal " + name);
                return false;
            }
            if (pulses != 1 || has(lang::kStaticOption) || io.options.size() != 1) {
                error(at,
                      name +
                          ", an illuminated push button, takes one of a_pulse, b_pulse, c_pulse");
                return false;
            }
            return true;
        case AddressKind::AnalogInput: {
            if (!target::contains(type.analogInputs, a.index)) {
                error(at, typeName + " has no analogue input " + name);
                return false;
            }
            const bool counter = has(lang::kCounterUpOption) || has(lang::kCounterUpDownOption);
            const bool analogue = has(lang::kVoltageOption) || has(lang::kCurrentOption);
            if (counter && !target::contains(type.counterInputs, a.index)) {
                error(at, name + " cannot count pulses on " + typeName +
                              (type.counterInputs.empty() ? "" : " (only IA0..IA3)"));
                return false;
            }
            if (counter || analogue) {
                if (io.options.size() != 1) {
                    error(at, name + " takes one of voltage, current, counter_up, counter_updown, "
                                     "or the options of an ordinary input");
                    return false;
                }
                return true;
            }
            return signalRules(true, false);
        }
        default:
            error(at, name + " takes no I/O options; only I, Q, IQ and IA terminals are declared");
            return false;
        }
    }

    const lang::Document& m_document;
    lang::Diagnostics& m_diagnostics;
    UnitSetups m_units;
    std::map<int, lang::UnitFamily> m_families;
};

} // namespace

UnitSetups collectUnits(const lang::Document& document, lang::Diagnostics& diagnostics) {
    return UnitCollector(document, diagnostics).run();
}

void collectSystemCalls(const lang::Document& document, UnitSetups& units,
                        lang::Diagnostics& diagnostics) {
    for (auto& [station, unit] : units) {
        if (!unit.program)
            continue;
        for (const auto& step : unit.program->steps)
            for (const auto& line : step.lines)
                if (auto call = readSystemCall(document, station, line, diagnostics))
                    unit.systemCalls.emplace(&line, std::move(*call));
    }
}

} // namespace rs::compiler
