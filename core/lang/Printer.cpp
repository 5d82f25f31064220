// SPDX-License-Identifier: GPL-3.0-or-later
#include "Printer.h"

#include "Keywords.h"

#include <cstdio>

namespace rs::lang {

namespace {

int characterCount(std::string_view text) {
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

void appendStatement(std::string& out, const Statement& statement);

// Ends the line whose code began at `codeStart` in `out`: its comment at the
// comment column, or a space after longer code.
void endLine(std::string& out, std::size_t codeStart, const std::optional<std::string>& comment) {
    if (comment) {
        const std::string_view code(out.data() + codeStart, out.size() - codeStart);
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
        const std::size_t start = out.size();
        out += '$';
        out += directive.keyword;
        if (!directive.text.empty()) {
            out += ' ';
            out += directive.text;
        }
        endLine(out, start, comment);
    }
    void operator()(const Declaration& declaration) const {
        const std::size_t start = out.size();
        out += printDeclaration(declaration);
        endLine(out, start, comment);
    }
    void operator()(const Statement& statement) const {
        const std::size_t start = out.size();
        appendStatement(out, statement);
        endLine(out, start, comment);
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

namespace {

// The printers append to one text: a large project's canonical text is
// printed at each compile, and a string made for every node and operand was
// most of the time it took (issue 23).

void appendOperand(std::string& out, const Operand& operand) {
    if (operand.isName())
        out += operand.name.str();
    else
        out += toString(operand.address);
}

void appendValue(std::string& out, const Value& value) {
    if (value.operand)
        appendOperand(out, *value.operand);
    else
        out += std::to_string(value.constant);
}

void appendExpression(std::string& out, const Expr& expr) {
    if (expr.negated)
        out += '/';
    switch (expr.kind) {
    case ExprKind::Or:
        for (std::size_t i = 0; i < expr.children.size(); ++i) {
            if (i)
                out += " + ";
            appendExpression(out, expr.children[i]);
        }
        return;
    case ExprKind::And:
        for (std::size_t i = 0; i < expr.children.size(); ++i) {
            if (i)
                out += " * ";
            const Expr& child = expr.children[i];
            if (child.kind == ExprKind::Or) {
                out += '(';
                appendExpression(out, child);
                out += ')';
            } else {
                appendExpression(out, child);
            }
        }
        return;
    case ExprKind::Contact:
        appendOperand(out, expr.operand);
        return;
    case ExprKind::Edge:
        out += expr.risingEdge ? kRisingEdgeWord : kFallingEdgeWord;
        out += '(';
        if (expr.operandNegated)
            out += '/';
        appendOperand(out, expr.operand);
        out += ')';
        return;
    case ExprKind::Timer:
        out += timerWord(expr.timer);
        out += '(';
        if (expr.preset.registerOperand)
            appendOperand(out, *expr.preset.registerOperand);
        else
            out += formatTime(expr.preset.hundredths);
        out += ')';
        return;
    case ExprKind::Compare:
        out += '(';
        appendOperand(out, expr.operand);
        out += compareWord(expr.compare);
        appendValue(out, expr.right);
        out += ')';
        return;
    }
}

void appendStatement(std::string& out, const Statement& statement) {
    switch (statement.kind) {
    case StatementKind::Coil:
        appendOperand(out, statement.target);
        break;
    case StatementKind::Set:
    case StatementKind::Reset:
    case StatementKind::SequenceReset:
    case StatementKind::Toggle:
        out += statementWord(statement.kind);
        out += '(';
        appendOperand(out, statement.target);
        out += ')';
        break;
    case StatementKind::Jump:
        out += kJumpWord;
        out += '(';
        if (statement.relativeJump)
            out += statement.jumpStep < 0 ? '-' : '+';
        out += std::to_string(statement.jumpStep < 0 ? -statement.jumpStep : statement.jumpStep);
        out += ')';
        break;
    case StatementKind::Assign:
        out += '(';
        out += printAssignment(*statement.assignment);
        out += ')';
        break;
    }
    if (statement.condition) {
        out += " = ";
        appendExpression(out, *statement.condition);
    }
}

// What an appender above writes, alone.
template <typename Node>
std::string printed(void (*append)(std::string&, const Node&), const Node& node) {
    std::string text;
    append(text, node);
    return text;
}

} // namespace

std::string printOperand(const Operand& operand) {
    return printed(appendOperand, operand);
}

std::string printValue(const Value& value) {
    return printed(appendValue, value);
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
    return printed(appendExpression, expr);
}

std::string printStatement(const Statement& statement) {
    return printed(appendStatement, statement);
}

std::string printDeclaration(const Declaration& declaration) {
    return std::visit(DeclarationPrinter{}, declaration.body);
}

namespace {

// `declarations` of unit i, or its own when null.
std::string printDocument(const std::vector<Line>& preamble, const std::vector<UnitProgram>& units,
                          const std::vector<std::vector<Line>>* declarations,
                          std::size_t expectedSize) {
    std::string out;
    out.reserve(expectedSize);
    printLines(out, preamble);
    for (std::size_t i = 0; i < units.size(); ++i) {
        const UnitProgram& unit = units[i];
        std::visit(LinePrinter{out, unit.header.comment}, unit.header.body);
        printLines(out, declarations ? (*declarations)[i] : unit.declarations);
        for (const auto& step : unit.steps) {
            const std::size_t start = out.size();
            out += toString(step.address);
            endLine(out, start, step.comment);
            printLines(out, step.lines);
        }
    }
    return out;
}

} // namespace

std::string print(const Document& document) {
    return printDocument(document.preamble, document.units, nullptr, 0);
}

std::string print(const std::vector<Line>& preamble, const std::vector<UnitProgram>& units,
                  const std::vector<std::vector<Line>>& declarations, std::size_t expectedSize) {
    return printDocument(preamble, units, &declarations, expectedSize);
}

} // namespace rs::lang
