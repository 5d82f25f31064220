// SPDX-License-Identifier: GPL-3.0-or-later
#include "InstanceExpansion.h"

#include "BodyTemplate.h"
#include "LibraryWords.h"
#include "compiler/SystemCall.h"
#include "lang/NameResolver.h"
#include "lang/Parser.h"
#include "lang/Printer.h"
#include "project/Annotation.h"

#include <algorithm>
#include <map>

namespace rs::blocks {

namespace {

std::optional<OperandKind> kindOfAddress(const lang::Address& address) {
    using K = lang::AddressKind;
    switch (address.kind) {
    case K::Input:
    case K::AnalogInput:
    case K::AsiInput:
        return OperandKind::Input;
    case K::Output:
    case K::AsiOutput:
        return OperandKind::Output;
    case K::InputOutput:
        return OperandKind::Input; // and Output: see allows()
    case K::Memory:
        return OperandKind::Memory;
    case K::GlobalMemory:
        return OperandKind::GlobalMemory;
    case K::SystemMemory:
        return OperandKind::SystemMemory;
    case K::RegisterBit:
        return OperandKind::RegisterBit;
    case K::Register:
        return OperandKind::Register;
    case K::DoubleRegister:
        return OperandKind::DoubleRegister;
    case K::SystemRegister:
        return OperandKind::SystemRegister;
    default:
        return std::nullopt;
    }
}

std::vector<OperandKind> allowedOperands(const Pin& pin) {
    return pin.operands.empty() ? possibleOperands(pin.kind, pin.direction) : pin.operands;
}

bool allows(const std::vector<OperandKind>& allowed, OperandKind kind) {
    return std::find(allowed.begin(), allowed.end(), kind) != allowed.end();
}

std::string kindsText(const std::vector<OperandKind>& kinds) {
    std::string text;
    for (std::size_t i = 0; i < kinds.size(); ++i) {
        if (i)
            text += i + 1 == kinds.size() ? " or " : ", ";
        text += std::string(wordOf(kinds[i]));
    }
    return text.empty() ? "nothing" : text;
}

// Why the operand cannot be bound to the pin; empty when it can.
std::string bindingProblem(const Pin& pin, const std::string& operand,
                           const std::map<std::string, lang::Address>& names, int station) {
    const std::vector<OperandKind> allowed = allowedOperands(pin);
    const std::string what =
        "pin " + pin.name + " takes " + kindsText(allowed) + ", not '" + operand + "'";
    if (canonicalInteger(operand) || (!operand.empty() && operand.front() == '-'))
        return allows(allowed, OperandKind::Number) ? "" : what;
    if (isTimeConstant(operand))
        return allows(allowed, OperandKind::TimeConstant) ? "" : what;
    const std::optional<lang::Address> address = operandAddress(names, operand);
    if (!address)
        return "pin " + pin.name + ": '" + operand + "' is neither an address nor a name unit " +
               std::to_string(station) + " sees";
    if (address->kind == lang::AddressKind::InputOutput &&
        (allows(allowed, OperandKind::Input) || allows(allowed, OperandKind::Output)))
        return {};
    const std::optional<OperandKind> kind = kindOfAddress(*address);
    return kind && allows(allowed, *kind) ? "" : what;
}

std::optional<lang::Address> take(PrivateVariables& variables, PrivateKind kind) {
    switch (kind) {
    case PrivateKind::Memory:
        return variables.memory();
    case PrivateKind::Register:
        return variables.registerWord();
    case PrivateKind::DoubleRegister:
        return variables.doubleRegister();
    }
    return std::nullopt;
}

std::optional<PrivateKind> standInKind(const Pin& pin) {
    switch (pin.kind) {
    case PinKind::Bit:
        return PrivateKind::Memory;
    case PinKind::Register:
    case PinKind::Time:
        return PrivateKind::Register;
    case PinKind::DoubleRegister:
        return PrivateKind::DoubleRegister;
    case PinKind::Constant:
        return std::nullopt;
    }
    return std::nullopt;
}

bool fits(const Pin& pin, const compiler::SystemParameter& parameter) {
    const bool in = pin.direction == PinDirection::In;
    if (in != (parameter.direction == compiler::ParameterDirection::In))
        return false;
    switch (parameter.kind) {
    case compiler::ParameterKind::Bit:
        return pin.kind == PinKind::Bit;
    case compiler::ParameterKind::Register:
        return pin.kind == PinKind::Register;
    case compiler::ParameterKind::DoubleRegister:
        return pin.kind == PinKind::DoubleRegister;
    case compiler::ParameterKind::AnalogInput:
        return pin.kind == PinKind::Bit; // an input pin, bound to an IA
    }
    return false;
}

std::string parameterText(const compiler::SystemParameter& parameter) {
    static constexpr const char* kinds[] = {"bit", "register", "double-register", "bit"};
    return std::string(parameter.name) + " " +
           (parameter.direction == compiler::ParameterDirection::In ? "in " : "out ") +
           kinds[static_cast<int>(parameter.kind)];
}

// An address in its canonical spelling, as the statements around the call
// are written; a name or a number as it is.
std::string canonicalOperand(const std::string& operand) {
    const lang::AddressWord word = lang::readAddressWord(operand);
    return word.shape == lang::AddressWord::Shape::Variable ? lang::toString(word.address)
                                                            : operand;
}

void placeAt(lang::Operand& operand, lang::SourceLocation at) {
    operand.location = at;
}
void placeAt(lang::Value& value, lang::SourceLocation at) {
    value.location = at;
    if (value.operand)
        placeAt(*value.operand, at);
}
void placeAt(lang::Expr& expr, lang::SourceLocation at) {
    expr.location = at;
    placeAt(expr.operand, at);
    if (expr.preset.registerOperand)
        placeAt(*expr.preset.registerOperand, at);
    placeAt(expr.right, at);
    for (auto& child : expr.children)
        placeAt(child, at);
}
void placeAt(lang::Line& line, lang::SourceLocation at) {
    line.location = at;
    if (auto* statement = std::get_if<lang::Statement>(&line.body)) {
        statement->location = at;
        placeAt(statement->target, at);
        placeAt(statement->assignment->target, at);
        placeAt(statement->assignment->left, at);
        placeAt(statement->assignment->right, at);
        if (statement->condition)
            placeAt(*statement->condition, at);
    }
}

} // namespace

UnitFrame::UnitFrame(const lang::Document& document, int station)
    : m_station(station), m_names(unitNames(document, station)) {
    // What name resolution needs: the declarations (types for the rules of
    // names, the names themselves), without the code.
    for (const auto& line : document.preamble)
        if (std::holds_alternative<lang::Declaration>(line.body))
            m_frame.preamble.push_back(line);
    lang::UnitProgram unit;
    for (const auto& existing : document.units)
        if (existing.station() == station)
            unit.declarations = existing.declarations;
    unit.header.body = lang::Declaration{lang::ProgramDeclaration{station}, {}};
    m_frame.units.push_back(std::move(unit));
    m_head = "! pgm_pluto:" + std::string(station < 10 ? "0" : "") + std::to_string(station) +
             "\n" + lang::toString(lang::StepAddress{station, 0, 0}) + "\n";
}

std::vector<lang::Line> UnitFrame::read(const std::string& body, lang::Diagnostics& problems) {
    lang::ParseResult parsed = lang::parse(m_head + body);
    problems = std::move(parsed.diagnostics);
    if (lang::errorCount(problems) > 0 || parsed.document.units.empty())
        return {};
    auto& steps = m_frame.units.front().steps;
    steps = std::move(parsed.document.units.front().steps);
    const lang::Diagnostics resolved = lang::resolveNames(m_frame);
    problems.insert(problems.end(), resolved.begin(), resolved.end());
    std::vector<lang::Line> lines;
    if (!steps.empty())
        lines = std::move(steps.front().lines);
    steps.clear();
    return lines;
}

std::string standInName(const Pin& pin) {
    return "pin." + pin.name;
}

Expansion expandInstance(const BlockDefinition& block, BlockInstance& instance, UnitFrame& frame,
                         PrivateVariables& variables) {
    const int station = frame.station();
    Expansion expansion;
    const lang::SourceLocation at = instance.location;
    auto error = [&](std::string message, int column = 0) {
        expansion.diagnostics.push_back({lang::Severity::Error, at.line,
                                         column ? column : at.column,
                                         block.name + ": " + std::move(message)});
    };
    const auto& names = frame.names();

    for (const auto& binding : instance.pins)
        if (!block.findPin(binding.name)) {
            std::string pins;
            for (const auto& pin : block.pins)
                pins += (pins.empty() ? "" : ", ") + pin.name;
            error("no pin '" + binding.name + "'; its pins are " + pins, binding.column);
        }

    // What each placeholder is replaced with.
    std::map<std::string, std::string> pinValues;     // by pin name as the block spells it
    std::map<std::string, std::string> privateValues; // by private name
    std::vector<std::string> firstScan;               // lines put before the body

    // A private variable: the recorded one, or a new one.
    bool exhausted = false;
    auto privateOperand = [&](const std::string& recordName,
                              PrivateKind kind) -> std::optional<std::string> {
        if (const Binding* recorded = instance.findPrivate(recordName)) {
            const lang::AddressWord word = lang::readAddressWord(recorded->operand);
            if (word.shape != lang::AddressWord::Shape::Variable || word.address.unit != station) {
                error("#" + recordName + "=\"" + recorded->operand + "\" is no variable of unit " +
                          std::to_string(station),
                      recorded->column);
                return std::nullopt;
            }
            return recorded->operand;
        }
        if (exhausted)
            return std::nullopt; // said once
        const std::optional<lang::Address> address = take(variables, kind);
        if (!address) {
            error("unit " + std::to_string(station) + " has no free " + std::string(wordOf(kind)) +
                  " left for the instance's " + recordName);
            exhausted = true;
            return std::nullopt;
        }
        const std::string operand = lang::toString(*address);
        instance.privates.push_back({recordName, operand});
        return operand;
    };

    for (const auto& pin : block.pins) {
        if (const Binding* bound = instance.findPin(pin.name)) {
            if (const std::string problem = bindingProblem(pin, bound->operand, names, station);
                !problem.empty())
                error(problem, bound->column);
            pinValues[pin.name] = bound->operand;
            continue;
        }
        const bool input = pin.direction == PinDirection::In;
        if (input && !pin.defaultValue) {
            error("input " + pin.name + " is not bound and has no default");
            continue;
        }
        // The language has no time constant 0s00 (TON(0s00) does not compile),
        // so a time default of 0 is a register nothing writes: it holds 0.
        const bool zeroTime = input && pin.kind == PinKind::Time && *pin.defaultValue == "0s00";
        if (input && pin.kind != PinKind::Bit && !zeroTime) {
            pinValues[pin.name] = *pin.defaultValue;
            continue;
        }
        const std::optional<PrivateKind> kind = standInKind(pin);
        if (!kind) {
            error("output " + pin.name + " must be bound");
            continue;
        }
        const std::optional<std::string> operand = privateOperand(standInName(pin), *kind);
        if (!operand)
            continue;
        pinValues[pin.name] = *operand;
        if (input && *pin.defaultValue == "1")
            firstScan.push_back("S(" + *operand + ") = /" + *operand);
    }
    for (const auto& variable : block.privates)
        if (const auto operand = privateOperand(variable.name, variable.kind))
            privateValues[variable.name] = *operand;
    if (!expansion.ok())
        return expansion;

    std::string body;
    for (const auto& line : firstScan)
        body += line + "\n";
    if (block.kind == BlockKind::System) {
        // The call: each parameter of the instruction takes the pin of its name.
        const compiler::SystemInstruction* instruction =
            compiler::findSystemInstruction(block.systemInstruction);
        if (!instruction) {
            error("system instruction '" + block.systemInstruction +
                  "' is not one of this Rungsmith's; " +
                  compiler::systemInstructionHint(block.systemInstruction));
            return expansion;
        }
        project::Annotation call;
        call.kind = compiler::kSystemRecord;
        call.arguments.emplace_back(instruction->name);
        for (const auto& parameter : instruction->parameters) {
            const Pin* pin = block.findPin(parameter.name);
            if (!pin || !fits(*pin, parameter)) {
                error("the block does not fit its system instruction " +
                      std::string(instruction->name) + ", which needs the pin " +
                      parameterText(parameter));
                return expansion;
            }
            call.attributes.emplace_back(parameter.name, canonicalOperand(pinValues.at(pin->name)));
        }
        body += ";" + project::formatAnnotation(call) + "\n";
    }
    for (const auto& line : block.body) {
        const SubstitutedLine substituted =
            substitute(line, [&](const Placeholder& placeholder) -> std::string {
                if (placeholder.isPrivate)
                    return privateValues.at(block.findPrivate(placeholder.name)->name);
                return pinValues.at(block.findPin(placeholder.name)->name);
            });
        body += substituted.text + "\n";
    }

    lang::Diagnostics problems;
    std::vector<lang::Line> lines = frame.read(body, problems);
    for (const auto& problem : problems)
        if (problem.severity == lang::Severity::Error) {
            error("its statements do not read with these operands: " + problem.message);
            return expansion;
        }
    for (auto& line : lines) {
        placeAt(line, at);
        expansion.lines.push_back(std::move(line));
    }
    return expansion;
}

} // namespace rs::blocks
