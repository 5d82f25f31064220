// SPDX-License-Identifier: GPL-3.0-or-later
#include "Printer.h"

#include "Keywords.h"

#include <cstdio>

namespace rs::lang {

namespace {

int characterCount(const std::string& text) {
    int count = 0;
    for (unsigned char c : text)
        if ((c & 0xC0) != 0x80)
            ++count;
    return count;
}

std::string printAssignment(const Assignment& a) {
    const bool step = a.op == AssignOp::Increment || a.op == AssignOp::Decrement;
    return printOperand(a.target) + (step ? "" : " ") + printAssignmentOperation(a);
}

std::string station(int number) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%02d", number);
    return buffer;
}

struct DeclarationPrinter {
    std::string operator()(const IdDeclaration& d) const {
        return "! " + std::string(idKeyword(d.family)) + ":" + station(d.station) + "=" + d.idfix;
    }
    std::string operator()(const TypeDeclaration& d) const {
        std::string text =
            "! " + std::string(kTypeKeyword) + ":" + station(d.station) + "=" + d.type;
        if (d.instructionSet)
            text += "," + std::string(instructionSetWord(d.instructionSet));
        return text;
    }
    std::string operator()(const ProgramDeclaration& d) const {
        return "! " + std::string(kProgramKeyword) + ":" + station(d.station);
    }
    std::string operator()(const IoDeclaration& d) const {
        std::string text = "! " + printOperand(d.io);
        for (const auto& option : d.options)
            text += "," + option;
        return text;
    }
    std::string operator()(const NameDeclaration& d) const {
        return "! " + printOperand(d.variable) + "=" + d.name;
    }
};

void appendWithComment(std::string& out, const std::string& code,
                       const std::optional<std::string>& comment) {
    out += code;
    if (comment) {
        int width = characterCount(code);
        if (code.empty())
            width = 0;
        if (!code.empty() && width < kCommentColumn - 1)
            out.append(static_cast<std::size_t>(kCommentColumn - 1 - width), ' ');
        else if (!code.empty())
            out += ' ';
        out += ';';
        out += *comment;
    }
    out += '\n';
}

struct LinePrinter {
    std::string& out;
    const std::optional<std::string>& comment;

    void operator()(const BlankLine&) const { out += '\n'; }
    void operator()(const CommentLine& line) const {
        if (line.indented)
            out.append(kCommentColumn - 1, ' ');
        out += ';';
        out += line.text;
        out += '\n';
    }
    void operator()(const Directive& directive) const {
        std::string code = "$" + directive.keyword;
        if (!directive.text.empty())
            code += " " + directive.text;
        appendWithComment(out, code, comment);
    }
    void operator()(const Declaration& declaration) const {
        appendWithComment(out, printDeclaration(declaration), comment);
    }
    void operator()(const Statement& statement) const {
        appendWithComment(out, printStatement(statement), comment);
    }
};

void printLines(std::string& out, const std::vector<Line>& lines) {
    for (const auto& line : lines)
        std::visit(LinePrinter{out, line.comment}, line.body);
}

} // namespace

std::string formatTime(int hundredths) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%ds%02d", hundredths / 100, hundredths % 100);
    return buffer;
}

std::string printOperand(const Operand& operand) {
    return operand.isName() ? operand.name.str() : toString(operand.address);
}

std::string printValue(const Value& value) {
    if (value.operand)
        return printOperand(*value.operand);
    return std::to_string(value.constant);
}

std::string printAssignmentOperation(const Assignment& a) {
    const std::string op(assignWord(a.op));
    switch (a.op) {
    case AssignOp::Increment:
    case AssignOp::Decrement:
        return op;
    case AssignOp::Binary:
        return op + " " + printValue(a.left) + " " + std::string(binaryWord(a.binary)) + " " +
               printValue(a.right);
    default:
        return op + " " + printValue(a.left);
    }
}

std::string printExpression(const Expr& expr) {
    std::string text = expr.negated ? "/" : "";
    switch (expr.kind) {
    case ExprKind::Or:
        for (std::size_t i = 0; i < expr.children.size(); ++i) {
            if (i)
                text += " + ";
            text += printExpression(expr.children[i]);
        }
        return text;
    case ExprKind::And:
        for (std::size_t i = 0; i < expr.children.size(); ++i) {
            if (i)
                text += " * ";
            const Expr& child = expr.children[i];
            if (child.kind == ExprKind::Or)
                text += "(" + printExpression(child) + ")";
            else
                text += printExpression(child);
        }
        return text;
    case ExprKind::Contact:
        return text + printOperand(expr.operand);
    case ExprKind::Edge:
        return text + std::string(expr.risingEdge ? kRisingEdgeWord : kFallingEdgeWord) + "(" +
               (expr.operandNegated ? "/" : "") + printOperand(expr.operand) + ")";
    case ExprKind::Timer:
        text += timerWord(expr.timer);
        text += '(';
        text += expr.preset.registerOperand ? printOperand(*expr.preset.registerOperand)
                                            : formatTime(expr.preset.hundredths);
        return text + ")";
    case ExprKind::Compare:
        return text + "(" + printOperand(expr.operand) + std::string(compareWord(expr.compare)) +
               printValue(expr.right) + ")";
    }
    return text;
}

std::string printStatement(const Statement& statement) {
    std::string text;
    switch (statement.kind) {
    case StatementKind::Coil:
        text = printOperand(statement.target);
        break;
    case StatementKind::Set:
    case StatementKind::Reset:
    case StatementKind::SequenceReset:
    case StatementKind::Toggle:
        text =
            std::string(statementWord(statement.kind)) + "(" + printOperand(statement.target) + ")";
        break;
    case StatementKind::Jump:
        text = std::string(kJumpWord) + "(";
        if (statement.relativeJump)
            text += statement.jumpStep < 0 ? "-" : "+";
        text += std::to_string(statement.jumpStep < 0 ? -statement.jumpStep : statement.jumpStep);
        text += ")";
        break;
    case StatementKind::Assign:
        text = "(" + printAssignment(*statement.assignment) + ")";
        break;
    }
    if (statement.condition)
        text += " = " + printExpression(*statement.condition);
    return text;
}

std::string printDeclaration(const Declaration& declaration) {
    return std::visit(DeclarationPrinter{}, declaration.body);
}

namespace {

// `declarations` of unit i, or its own when null.
std::string printDocument(const std::vector<Line>& preamble, const std::vector<UnitProgram>& units,
                          const std::vector<std::vector<Line>>* declarations) {
    std::string out;
    printLines(out, preamble);
    for (std::size_t i = 0; i < units.size(); ++i) {
        const UnitProgram& unit = units[i];
        std::visit(LinePrinter{out, unit.header.comment}, unit.header.body);
        printLines(out, declarations ? (*declarations)[i] : unit.declarations);
        for (const auto& step : unit.steps) {
            appendWithComment(out, toString(step.address), step.comment);
            printLines(out, step.lines);
        }
    }
    return out;
}

} // namespace

std::string print(const Document& document) {
    return printDocument(document.preamble, document.units, nullptr);
}

std::string print(const std::vector<Line>& preamble, const std::vector<UnitProgram>& units,
                  const std::vector<std::vector<Line>>& declarations) {
    return printDocument(preamble, units, &declarations);
}

} // namespace rs::lang
