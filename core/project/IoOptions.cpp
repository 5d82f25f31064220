// SPDX-License-Identifier: GPL-3.0-or-later
#include "IoOptions.h"

#include "BlankLines.h"
#include "UnitSettings.h"
#include "lang/Keywords.h"

#include <algorithm>

namespace rs::project {

namespace {

using lang::AddressKind;
using target::contains;

bool isInput(const target::UnitTypeInfo& type, int number) {
    return contains(type.globalInputs, number) || contains(type.localInputs, number);
}

bool isDynamic(SignalShape shape) {
    return shape == SignalShape::APulse || shape == SignalShape::BPulse ||
           shape == SignalShape::CPulse;
}

std::string_view shapeWord(SignalShape shape) {
    switch (shape) {
    case SignalShape::Static:
        return lang::kStaticOption;
    case SignalShape::APulse:
        return lang::kAPulseOption;
    case SignalShape::BPulse:
        return lang::kBPulseOption;
    case SignalShape::CPulse:
        return lang::kCPulseOption;
    case SignalShape::None:
        break;
    }
    return {};
}

std::optional<SignalShape> shapeOfWord(std::string_view word) {
    for (SignalShape shape :
         {SignalShape::Static, SignalShape::APulse, SignalShape::BPulse, SignalShape::CPulse})
        if (shapeWord(shape) == word)
            return shape;
    return std::nullopt;
}

template <typename T> bool has(const std::vector<T>& list, T value) {
    return std::find(list.begin(), list.end(), value) != list.end();
}

const lang::IoDeclaration* ioOf(const lang::Line& line) {
    if (auto* declaration = std::get_if<lang::Declaration>(&line.body))
        return std::get_if<lang::IoDeclaration>(&declaration->body);
    return nullptr;
}

} // namespace

std::string Terminal::label() const {
    std::string prefix;
    switch (kind) {
    case TerminalKind::Input:
        prefix = "I";
        break;
    case TerminalKind::Configurable:
        prefix = "IQ";
        break;
    case TerminalKind::Analogue:
        prefix = "IA";
        break;
    case TerminalKind::SafetyOutput:
        prefix = "Q";
        break;
    }
    return prefix + std::to_string(station) + "." + std::to_string(number);
}

std::vector<Terminal> terminalsOf(const target::UnitTypeInfo& type, int station) {
    std::vector<Terminal> terminals;
    for (int number = 0; number < 100; ++number) {
        if (contains(type.analogInputs, number))
            terminals.push_back({TerminalKind::Analogue, station, number});
        else if (contains(type.configurableTerminals, number))
            terminals.push_back({TerminalKind::Configurable, station, number});
        else if (isInput(type, number))
            terminals.push_back({TerminalKind::Input, station, number});
    }
    if (type.testPulsesCanBeDisabled)
        for (int number : {2, 3})
            if (contains(type.globalSafetyOutputs, number))
                terminals.push_back({TerminalKind::SafetyOutput, station, number});
    return terminals;
}

std::vector<SignalType> signalTypes(const target::UnitTypeInfo& type, const Terminal& terminal) {
    switch (terminal.kind) {
    case TerminalKind::Input:
        return {SignalType::Undefined, SignalType::Input};
    case TerminalKind::Configurable: {
        std::vector<SignalType> types{SignalType::Undefined};
        if (isInput(type, terminal.number))
            types.push_back(SignalType::Input);
        if (contains(type.nonSafetyOutputs, terminal.number))
            types.push_back(SignalType::Output);
        types.push_back(SignalType::LightButton);
        return types;
    }
    case TerminalKind::Analogue: {
        std::vector<SignalType> types{SignalType::Undefined, SignalType::Input, SignalType::Voltage,
                                      SignalType::Current};
        if (contains(type.counterInputs, terminal.number)) {
            types.push_back(SignalType::CounterUp);
            types.push_back(SignalType::CounterUpDown);
        }
        return types;
    }
    case TerminalKind::SafetyOutput:
        break; // only the test-pulse option
    }
    return {};
}

std::vector<SignalShape> signalShapes(const Terminal& terminal, SignalType signal) {
    if (terminal.kind == TerminalKind::SafetyOutput)
        return {};
    switch (signal) {
    case SignalType::Input:
    case SignalType::Output:
        return {SignalShape::Static, SignalShape::APulse, SignalShape::BPulse, SignalShape::CPulse};
    case SignalType::LightButton:
        return {SignalShape::APulse, SignalShape::BPulse, SignalShape::CPulse};
    default:
        return {};
    }
}

std::vector<TerminalOption> terminalOptions(const target::UnitTypeInfo& type,
                                            const Terminal& terminal,
                                            const TerminalSetting& setting) {
    if (terminal.kind == TerminalKind::SafetyOutput)
        return {TerminalOption::NoTestPulse};
    if (setting.type != SignalType::Input)
        return {};
    // Non_Inv belongs to the dynamic signals; x_talk to dynamic inputs on the
    // terminals that can also be outputs (Part 2, 5.3, cross talk).
    std::vector<TerminalOption> options;
    if (isDynamic(setting.shape))
        options.push_back(TerminalOption::NonInverted);
    options.push_back(TerminalOption::NoFilter);
    if (isDynamic(setting.shape) && terminal.kind == TerminalKind::Configurable &&
        contains(type.configurableTerminals, terminal.number))
        options.push_back(TerminalOption::CrossTalk);
    return options;
}

TerminalSetting legalSetting(const target::UnitTypeInfo& type, const Terminal& terminal,
                             TerminalSetting setting) {
    TerminalSetting legal;
    if (terminal.kind != TerminalKind::SafetyOutput) {
        if (!has(signalTypes(type, terminal), setting.type))
            return legal;
        legal.type = setting.type;
        const auto shapes = signalShapes(terminal, legal.type);
        if (!shapes.empty())
            legal.shape = has(shapes, setting.shape) ? setting.shape : shapes.front();
    }
    const auto options = terminalOptions(type, terminal, legal);
    legal.nonInverted = setting.nonInverted && has(options, TerminalOption::NonInverted);
    legal.noFilter = setting.noFilter && has(options, TerminalOption::NoFilter);
    legal.crossTalk = setting.crossTalk && has(options, TerminalOption::CrossTalk);
    legal.noTestPulse = setting.noTestPulse && has(options, TerminalOption::NoTestPulse);
    return legal;
}

std::optional<lang::IoDeclaration> ioDeclaration(const Terminal& terminal,
                                                 const TerminalSetting& setting) {
    lang::IoDeclaration declaration;
    declaration.io.address = {AddressKind::Input, terminal.station, terminal.number};
    auto& words = declaration.options;
    if (terminal.kind == TerminalKind::SafetyOutput) {
        if (!setting.noTestPulse)
            return std::nullopt;
        declaration.io.address.kind = AddressKind::Output;
        words.emplace_back(lang::kNoTestPulseOption);
        return declaration;
    }
    const bool analogue = terminal.kind == TerminalKind::Analogue;
    switch (setting.type) {
    case SignalType::Undefined:
        return std::nullopt;
    case SignalType::Input:
        declaration.io.address.kind = analogue ? AddressKind::AnalogInput : AddressKind::Input;
        words.emplace_back(shapeWord(setting.shape));
        if (setting.nonInverted)
            words.emplace_back(lang::kNonInvertedOption);
        if (setting.noFilter)
            words.emplace_back(lang::kNoFilterOption);
        if (setting.crossTalk)
            words.emplace_back(lang::kCrossTalkOption);
        return declaration;
    case SignalType::Output:
        declaration.io.address.kind = AddressKind::Output;
        words.emplace_back(shapeWord(setting.shape));
        return declaration;
    case SignalType::LightButton:
        declaration.io.address.kind = AddressKind::InputOutput;
        words.emplace_back(shapeWord(setting.shape));
        return declaration;
    case SignalType::Voltage:
    case SignalType::Current:
    case SignalType::CounterUp:
    case SignalType::CounterUpDown:
        declaration.io.address.kind = AddressKind::AnalogInput;
        words.emplace_back(setting.type == SignalType::Voltage     ? lang::kVoltageOption
                           : setting.type == SignalType::Current   ? lang::kCurrentOption
                           : setting.type == SignalType::CounterUp ? lang::kCounterUpOption
                                                                   : lang::kCounterUpDownOption);
        return declaration;
    }
    return std::nullopt;
}

std::optional<Terminal> terminalOf(const target::UnitTypeInfo& type,
                                   const lang::IoDeclaration& declaration) {
    const lang::Address& a = declaration.io.address;
    Terminal terminal{TerminalKind::Input, a.unit, a.index};
    switch (a.kind) {
    case AddressKind::Input:
        if (contains(type.analogInputs, a.index))
            return std::nullopt;
        if (contains(type.configurableTerminals, a.index))
            terminal.kind = TerminalKind::Configurable;
        else if (!isInput(type, a.index))
            return std::nullopt;
        return terminal;
    case AddressKind::Output:
        if (contains(type.configurableTerminals, a.index)) {
            terminal.kind = TerminalKind::Configurable;
            return terminal;
        }
        terminal.kind = TerminalKind::SafetyOutput;
        for (const Terminal& listed : terminalsOf(type, a.unit))
            if (listed == terminal)
                return terminal;
        return std::nullopt;
    case AddressKind::InputOutput:
        if (!contains(type.configurableTerminals, a.index))
            return std::nullopt;
        terminal.kind = TerminalKind::Configurable;
        return terminal;
    case AddressKind::AnalogInput:
        if (!contains(type.analogInputs, a.index))
            return std::nullopt;
        terminal.kind = TerminalKind::Analogue;
        return terminal;
    default:
        return std::nullopt;
    }
}

TerminalSetting settingOf(const Terminal& terminal, const lang::IoDeclaration& declaration) {
    TerminalSetting setting;
    const auto& words = declaration.options;
    auto word = [&](std::string_view w) {
        return has(words, std::string(w));
    };
    if (terminal.kind == TerminalKind::SafetyOutput) {
        setting.noTestPulse = word(lang::kNoTestPulseOption);
        return setting;
    }
    for (const auto& w : words)
        if (auto shape = shapeOfWord(w))
            setting.shape = *shape;
    switch (declaration.io.address.kind) {
    case AddressKind::Output:
        setting.type = SignalType::Output;
        return setting;
    case AddressKind::InputOutput:
        setting.type = SignalType::LightButton;
        return setting;
    default:
        break;
    }
    setting.type = word(lang::kVoltageOption)         ? SignalType::Voltage
                   : word(lang::kCurrentOption)       ? SignalType::Current
                   : word(lang::kCounterUpOption)     ? SignalType::CounterUp
                   : word(lang::kCounterUpDownOption) ? SignalType::CounterUpDown
                                                      : SignalType::Input;
    setting.nonInverted = word(lang::kNonInvertedOption);
    setting.noFilter = word(lang::kNoFilterOption);
    setting.crossTalk = word(lang::kCrossTalkOption);
    return setting;
}

TerminalSetting terminalSetting(const Project& project, const Terminal& terminal) {
    const target::UnitTypeInfo& type = unitTypeOf(project, terminal.station);
    for (const auto& unit : project.program.units) {
        if (unit.station() != terminal.station)
            continue;
        for (const auto& line : unit.declarations)
            if (const auto* io = ioOf(line))
                if (terminalOf(type, *io) == terminal)
                    return settingOf(terminal, *io);
    }
    return {};
}

TerminalSetting setTerminalSetting(Project& project, const Terminal& terminal,
                                   const TerminalSetting& setting) {
    const target::UnitTypeInfo& type = unitTypeOf(project, terminal.station);
    const TerminalSetting legal = legalSetting(type, terminal, setting);
    const std::vector<Terminal> order = terminalsOf(type, terminal.station);
    auto rank = [&](const Terminal& t) {
        return std::find(order.begin(), order.end(), t) - order.begin();
    };
    std::vector<lang::Line>& lines = programOf(project, terminal.station).declarations;
    const std::optional<lang::IoDeclaration> wanted = ioDeclaration(terminal, legal);

    bool written = false;
    std::ptrdiff_t afterEarlier = -1; // just after the last declaration of an earlier terminal
    std::ptrdiff_t firstIo = -1;
    std::ptrdiff_t firstName = -1;
    for (std::size_t i = 0; i < lines.size();) {
        const auto at = static_cast<std::ptrdiff_t>(i);
        const auto* io = ioOf(lines[i]);
        if (!io) {
            if (auto* d = std::get_if<lang::Declaration>(&lines[i].body);
                d && firstName < 0 && std::holds_alternative<lang::NameDeclaration>(d->body))
                firstName = at;
            ++i;
            continue;
        }
        const std::optional<Terminal> declared = terminalOf(type, *io);
        if (declared == terminal) {
            if (wanted && !written) {
                std::get<lang::Declaration>(lines[i].body).body = *wanted;
                written = true;
                ++i;
            } else {
                lines.erase(lines.begin() + at);
            }
            continue;
        }
        if (firstIo < 0)
            firstIo = at;
        if (!declared || rank(*declared) < rank(terminal))
            afterEarlier = at + 1;
        ++i;
    }
    if (wanted && !written) {
        const std::ptrdiff_t insertAt = afterEarlier >= 0 ? afterEarlier
                                        : firstIo >= 0    ? firstIo
                                        : firstName >= 0
                                            ? firstName
                                            : static_cast<std::ptrdiff_t>(lines.size());
        lines.insert(lines.begin() + insertAt,
                     lang::Line{lang::Declaration{*wanted, {}}, std::nullopt, {}});
    }
    tidyBlankLines(project.program);
    return legal;
}

} // namespace rs::project
