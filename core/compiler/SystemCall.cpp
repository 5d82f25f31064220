// SPDX-License-Identifier: GPL-3.0-or-later
#include "SystemCall.h"

#include "lang/NameResolver.h"
#include "lang/Printer.h"
#include "project/Annotation.h"
#include "project/Utf8Text.h"

#include <charconv>
#include <string>

namespace rs::compiler {

namespace {

bool fits(ParameterKind kind, const lang::Address& address) {
    using K = lang::AddressKind;
    switch (kind) {
    case ParameterKind::Bit:
        return address.isBit();
    case ParameterKind::Register:
        return address.kind == K::Register || address.kind == K::DoubleRegisterLow ||
               address.kind == K::DoubleRegisterHigh || address.kind == K::SystemRegister;
    case ParameterKind::DoubleRegister:
        return address.kind == K::DoubleRegister;
    case ParameterKind::AnalogInput:
        return address.kind == K::AnalogInput;
    }
    return false;
}

std::string kindText(const SystemParameter& parameter) {
    std::string text;
    switch (parameter.kind) {
    case ParameterKind::Bit:
        text = "a bit";
        break;
    case ParameterKind::Register:
        text = "a register (R, a half of a DR, SR)";
        break;
    case ParameterKind::DoubleRegister:
        text = "a double register (DR)";
        break;
    case ParameterKind::AnalogInput:
        text = "an analogue input (IA)";
        break;
    }
    return parameter.takesNumber ? text + " or a number" : text;
}

bool isInteger(std::string_view text) {
    if (!text.empty() && text.front() == '-')
        text.remove_prefix(1);
    return !text.empty() && text.find_first_not_of("0123456789") == std::string_view::npos;
}

} // namespace

bool isSystemRecord(const lang::Line& line) {
    const auto record = project::annotationOn(line);
    return record && record->kind == kSystemRecord;
}

std::optional<SystemCall> readSystemCall(const lang::Document& document, int station,
                                         const lang::Line& line, lang::Diagnostics& diagnostics) {
    const auto record = project::annotationOn(line);
    if (!record || record->kind != kSystemRecord)
        return std::nullopt;
    const lang::SourceLocation at = line.location;
    const std::size_t errorsBefore = static_cast<std::size_t>(lang::errorCount(diagnostics));
    auto error = [&](std::string message, int column = 0) {
        diagnostics.push_back(
            {lang::Severity::Error, at.line, column ? column : at.column, std::move(message)});
    };
    if (record->arguments.size() != 1) {
        error("@system needs one system instruction's name, as in ;@system RegisterValid "
              "Input=\"R1.5\" Valid=\"M0.1\" Value=\"R0.7\"");
        return std::nullopt;
    }
    const std::string& name = record->arguments.front();
    const SystemInstruction* instruction = findSystemInstruction(name);
    if (!instruction) {
        error("unknown system instruction '" + name + "'; " + systemInstructionHint(name));
        return std::nullopt;
    }
    const std::string called(instruction->name);

    // The column of each key in turn: keys stand in the text in their order.
    const std::string_view text = std::get<lang::CommentLine>(line.body).text;
    std::size_t searched = 0;
    auto columnOf = [&](const std::string& key) {
        const std::size_t found = text.find(" " + key + "=", searched);
        if (found == std::string_view::npos)
            return 0;
        searched = found + key.size() + 2;
        return at.column + project::characterColumn(text, found + 1);
    };
    struct Given {
        std::string text;
        int column = 0;
    };
    const auto& parameters = instruction->parameters;
    std::vector<std::optional<Given>> given(parameters.size());
    for (const auto& [key, value] : record->attributes) {
        const int column = columnOf(key);
        const SystemParameter* parameter = findParameter(*instruction, key);
        if (!parameter) {
            std::string names;
            for (const auto& p : parameters)
                names += (names.empty() ? "" : ", ") + std::string(p.name);
            error(called + " has no operand '" + key + "'; its operands are " + names, column);
            continue;
        }
        auto& slot = given[static_cast<std::size_t>(parameter - parameters.data())];
        if (slot) {
            error(called + ": operand " + std::string(parameter->name) + " is given twice", column);
            continue;
        }
        slot = Given{value, column};
    }
    for (std::size_t i = 0; i < parameters.size(); ++i)
        if (!given[i])
            error(called + ": operand " + std::string(parameters[i].name) + " is not given");
    if (static_cast<std::size_t>(lang::errorCount(diagnostics)) > errorsBefore)
        return std::nullopt;

    SystemCall call{instruction, {}, at};
    call.arguments.resize(parameters.size());
    std::vector<lang::Operand*> named;
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        const SystemParameter& parameter = parameters[i];
        const Given& operand = *given[i];
        lang::Value& value = call.arguments[i];
        value.location = {at.line, operand.column ? operand.column : at.column};
        const std::string what = called + ": operand " + std::string(parameter.name) + " takes " +
                                 kindText(parameter) + ", not '" + operand.text + "'";
        if (isInteger(operand.text)) {
            const char* end = operand.text.data() + operand.text.size();
            if (parameter.direction != ParameterDirection::In || !parameter.takesNumber)
                error(what, value.location.column);
            else if (std::from_chars(operand.text.data(), end, value.constant).ptr != end)
                error(called + ": operand " + std::string(parameter.name) + ": " + operand.text +
                          " is too large",
                      value.location.column);
            continue;
        }
        const lang::AddressWord word = lang::readAddressWord(operand.text);
        lang::Operand& variable = value.operand.emplace();
        variable.location = value.location;
        if (word.shape == lang::AddressWord::Shape::Variable) {
            variable.address = word.address;
        } else if (word.shape == lang::AddressWord::Shape::NotAnAddress && !operand.text.empty()) {
            variable.name = operand.text;
            named.push_back(&variable);
        } else {
            error(what, value.location.column);
        }
    }
    const lang::Diagnostics unresolved = lang::resolveOperands(document, station, named);
    diagnostics.insert(diagnostics.end(), unresolved.begin(), unresolved.end());
    if (static_cast<std::size_t>(lang::errorCount(diagnostics)) > errorsBefore)
        return std::nullopt;
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        const lang::Value& value = call.arguments[i];
        if (value.operand && !fits(parameters[i].kind, value.operand->address))
            error(called + ": operand " + std::string(parameters[i].name) + " takes " +
                      kindText(parameters[i]) + ", not " + lang::toString(value.operand->address),
                  value.location.column);
    }
    if (static_cast<std::size_t>(lang::errorCount(diagnostics)) > errorsBefore)
        return std::nullopt;
    return call;
}

} // namespace rs::compiler
