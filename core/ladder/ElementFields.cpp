// SPDX-License-Identifier: GPL-3.0-or-later
#include "ElementFields.h"

#include "ElementVocabulary.h"
#include "LadderToText.h"
#include "lang/Keywords.h"
#include "lang/Printer.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace rs::ladder {

namespace {

// A word as typed, printed back as it is.
lang::Operand typed(const std::string& word) {
    lang::Operand operand;
    operand.name = word;
    return operand;
}

lang::Value typedValue(const std::string& word) {
    return lang::Value{typed(word), 0, {}};
}

// The operator a value field starts with, longest spelling first, and the rest.
template <typename Op>
std::optional<std::pair<Op, std::string>>
splitOperator(const std::string& value, std::optional<Op> (*read)(std::string_view)) {
    for (std::size_t length = 2; length > 0; --length)
        if (value.size() >= length)
            if (std::optional<Op> op = read(std::string_view(value).substr(0, length)))
                return std::pair{*op, trimmedField(std::string_view(value).substr(length))};
    return std::nullopt;
}

// "3", "+1", "-2": a step, or an offset from this one.
bool readJump(const std::string& text, ElementParts& parts) {
    std::string_view digits = text;
    parts.relativeJump = !digits.empty() && (digits.front() == '+' || digits.front() == '-');
    const bool back = parts.relativeJump && digits.front() == '-';
    if (parts.relativeJump)
        digits.remove_prefix(1);
    if (digits.empty() || digits.size() > 6 ||
        !std::all_of(digits.begin(), digits.end(),
                     [](unsigned char c) { return std::isdigit(c) != 0; }))
        return false;
    parts.jumpStep = std::stoi(std::string(digits)) * (back ? -1 : 1);
    return true;
}

std::string printed(const ElementNode& node) {
    if (const auto* expr = std::get_if<lang::Expr>(&node))
        return lang::printExpression(*expr);
    return lang::printStatement(std::get<lang::Statement>(node));
}

ElementFields fieldsOfNode(const ElementNode& node) {
    ElementFields fields;
    fields.kind = *kindOf(node);
    const ElementParts parts = partsOf(node);
    fields.negated = parts.negated;
    switch (infoOf(fields.kind).operandRole) {
    case OperandRole::Preset:
        fields.operand = parts.preset.registerOperand
                             ? lang::printOperand(*parts.preset.registerOperand)
                             : lang::formatTime(parts.preset.hundredths);
        break;
    case OperandRole::Step:
        fields.operand = (parts.relativeJump ? (parts.jumpStep < 0 ? "-" : "+") : "") +
                         std::to_string(std::abs(parts.jumpStep));
        break;
    default:
        fields.operand = (parts.operandNegated ? "/" : "") + lang::printOperand(parts.operand);
        break;
    }
    if (fields.kind == ElementKind::Comparison)
        fields.value =
            std::string(lang::compareWord(parts.compare)) + lang::printValue(parts.right);
    else if (fields.kind == ElementKind::Arithmetic)
        fields.value = lang::printAssignmentOperation(parts.assignment);
    return fields;
}

} // namespace

ElementFields fieldsOf(const Element& element) {
    return fieldsOfNode(toExpr(Circuit::of(element)));
}

ElementFields fieldsOf(const Output& output) {
    ElementFields fields = fieldsOfNode(toStatement(output));
    if (output.comment)
        fields.comment = trimmedField(*output.comment);
    return fields;
}

FieldsText textOf(const ElementFields& fields) {
    const ElementKindInfo& info = infoOf(fields.kind);
    const std::string operand = trimmedField(fields.operand);
    const std::string value = trimmedField(fields.value);
    if (operand.empty())
        return {{}, info.output ? "the output is empty" : "the element is empty"};
    ElementParts parts;
    parts.negated = info.canNegate && fields.negated;
    switch (info.operandRole) {
    case OperandRole::Preset:
        parts.preset.registerOperand = typed(operand);
        break;
    case OperandRole::Step:
        if (!readJump(operand, parts))
            return {{}, "write a step number, or +n / -n for a step after or before this one"};
        break;
    default:
        parts.operand = typed(operand);
        break;
    }
    if (fields.kind == ElementKind::Comparison) {
        const auto split = splitOperator<lang::CompareOp>(value, &lang::compareOpOf);
        if (!split)
            return {{}, "start the value with a comparison: =, >, <, >= or <="};
        parts.compare = split->first;
        parts.right = typedValue(split->second);
    } else if (fields.kind == ElementKind::Arithmetic) {
        const auto split = splitOperator<lang::AssignOp>(value, &lang::assignOpOf);
        if (!split)
            return {{}, "start the value with an assignment: ++, --, +=, -=, *=, /= or ="};
        parts.assignment.op = split->first;
        const bool step =
            split->first == lang::AssignOp::Increment || split->first == lang::AssignOp::Decrement;
        if (step != split->second.empty())
            return {{}, step ? "nothing follows ++ or --" : "write a value after the operator"};
        // "= a + b" stays one typed value: the language reads which assignment it is.
        parts.assignment.left = typedValue(split->second);
    }
    return {printed(makeNode(fields.kind, parts)), {}};
}

std::string trimmedField(std::string_view text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos)
        return {};
    const auto last = text.find_last_not_of(" \t");
    return std::string(text.substr(first, last - first + 1));
}

} // namespace rs::ladder
