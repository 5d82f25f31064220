// SPDX-License-Identifier: GPL-3.0-or-later
#include "ElementText.h"

#include "ElementFields.h"
#include "LadderToText.h"
#include "SymbolTable.h"
#include "TextToLadder.h"
#include "lang/NameResolver.h"
#include "lang/OperandWalk.h"
#include "lang/Parser.h"
#include "lang/Printer.h"

namespace rs::ladder {

namespace {

// The unit's names around one statement: the project's preamble and the
// unit's declarations, then a step holding `statement` alone.
struct StatementReading {
    std::optional<lang::Statement> statement;
    std::string error;
};

// An address typed where the unit has a name for it is written with the
// name, as the program writes its other uses (issue 17: "i0.1" for EStop).
void nameOperands(lang::Statement& statement, const SymbolTable& symbols) {
    lang::forEachOperand(statement, [&symbols](lang::Operand& operand) {
        if (!operand.isName() && operand.address.valid())
            operand.name = symbols.nameOf(operand.address);
    });
}

StatementReading readStatement(const lang::Document& document, int station,
                               const std::string& statement) {
    lang::Document names;
    names.preamble = document.preamble;
    lang::UnitProgram unit;
    for (const auto& existing : document.units)
        if (existing.station() == station)
            unit = existing;
    unit.header.body = lang::Declaration{lang::ProgramDeclaration{station}, {}};
    unit.header.comment.reset();
    unit.steps.clear();
    names.units.push_back(unit);
    const std::string text = lang::print(names) + lang::toString(lang::StepAddress{station, 0, 0}) +
                             "\n" + statement + "\n";
    lang::ParseResult parsed = lang::parse(text);
    lang::Diagnostics diagnostics = parsed.diagnostics;
    if (lang::errorCount(diagnostics) == 0) {
        const lang::Diagnostics resolved = lang::resolveNames(parsed.document);
        diagnostics.insert(diagnostics.end(), resolved.begin(), resolved.end());
    }
    for (const auto& diagnostic : diagnostics)
        if (diagnostic.severity == lang::Severity::Error)
            return {std::nullopt, diagnostic.message};
    const auto& units = parsed.document.units;
    if (units.empty() || units.back().steps.empty())
        return {std::nullopt, "not a statement"};
    const SymbolTable symbols = SymbolTable::of(document, station);
    for (const auto& line : units.back().steps.back().lines)
        if (const auto* read = std::get_if<lang::Statement>(&line.body)) {
            lang::Statement named = *read;
            nameOperands(named, symbols);
            return {named, {}};
        }
    return {std::nullopt, "nothing to read"};
}

} // namespace

ElementReading readElement(const lang::Document& document, int station, std::string_view text) {
    const std::string element = trimmedField(text);
    if (element.empty())
        return {std::nullopt, "the element is empty"};
    const std::string coil = lang::toString(lang::Address{lang::AddressKind::Memory, station, 0});
    StatementReading read = readStatement(document, station, coil + " = " + element);
    if (!read.statement)
        return {std::nullopt, read.error};
    if (!read.statement->condition)
        return {std::nullopt, "not an element"};
    Circuit circuit = toCircuit(*read.statement->condition);
    if (!circuit.isElement())
        return {std::nullopt, "write one element, not a condition of several"};
    return {circuit.element, {}};
}

OutputReading readOutput(const lang::Document& document, int station, std::string_view text) {
    const std::string output = trimmedField(text);
    if (output.empty())
        return {std::nullopt, "the output is empty"};
    StatementReading read = readStatement(document, station, output);
    if (!read.statement)
        return {std::nullopt, read.error};
    if (read.statement->condition)
        return {std::nullopt, "write the output alone, without its condition"};
    return {toOutput(*read.statement, std::nullopt), {}};
}

std::string elementText(const Element& element) {
    return lang::printExpression(toExpr(Circuit::of(element)));
}

std::string outputText(const Output& output) {
    Rung rung;
    rung.outputs.push_back(output);
    rung.outputs.back().comment.reset();
    const std::vector<lang::Line> lines = toLines(rung);
    return lang::printStatement(std::get<lang::Statement>(lines.front().body));
}

} // namespace rs::ladder
