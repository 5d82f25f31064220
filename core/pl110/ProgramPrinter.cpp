// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProgramText.h"

namespace rs::pl110 {

std::string operandText(const Operand& operand) {
    return operand.isName() ? operand.name : toString(operand.address);
}

std::string valueText(const Value& value) {
    return value.isConstant() ? std::to_string(value.constant) : operandText(*value.operand);
}

std::string_view compareWord(CompareOp op) {
    switch (op) {
    case CompareOp::Equal:
        return "=";
    case CompareOp::NotEqual:
        return "<>";
    case CompareOp::Greater:
        return ">";
    case CompareOp::Less:
        return "<";
    case CompareOp::GreaterEqual:
        return ">=";
    case CompareOp::LessEqual:
        return "<=";
    }
    return "=";
}

std::string_view formulaWord(FormulaOp op) {
    switch (op) {
    case FormulaOp::Add:
        return "+";
    case FormulaOp::Sub:
        return "-";
    case FormulaOp::Mul:
        return "*";
    case FormulaOp::Div:
        return "/";
    case FormulaOp::Or:
        return "|";
    case FormulaOp::And:
        return "&";
    case FormulaOp::Xor:
        return "^";
    case FormulaOp::ShiftLeft:
        return "<<";
    case FormulaOp::ShiftRight:
        return ">>";
    }
    return "+";
}

std::string_view timeBaseWord(TimeBase base) {
    switch (base) {
    case TimeBase::Ms10:
        return "10ms";
    case TimeBase::Ms100:
        return "100ms";
    case TimeBase::S1:
        return "1s";
    }
    return "100ms";
}

std::string_view timerWord(TimerType type) {
    switch (type) {
    case TimerType::OnDelay:
        return "TON";
    case TimerType::OffDelay:
        return "TOFF";
    case TimerType::Retentive:
        return "TONR";
    }
    return "TON";
}

std::string_view counterWord(CounterType type) {
    return type == CounterType::Up ? "MUP" : "MDOWN";
}

std::string_view inputWord(CounterInput input) {
    switch (input) {
    case CounterInput::Up:
        return "UP";
    case CounterInput::Down:
        return "DOWN";
    case CounterInput::Reset:
        return "RESET";
    }
    return "UP";
}

namespace {

constexpr std::size_t kCommentColumn = 31; // trailing comments line up here, as in Pluto files

std::string elementText(const Element& element) {
    switch (element.kind) {
    case ElementKind::NormallyOpen:
        return operandText(element.operand);
    case ElementKind::NormallyClosed:
        return "/" + operandText(element.operand);
    case ElementKind::Compare:
        return "(" + valueText(element.left) + std::string(compareWord(element.compare)) +
               valueText(element.right) + ")";
    case ElementKind::Not:
        return "NOT";
    case ElementKind::RisingEdge:
        return "P";
    case ElementKind::FallingEdge:
        return "N";
    }
    return {};
}

std::string circuitText(const Circuit& circuit) {
    if (circuit.isElement())
        return elementText(circuit.element);
    std::string text;
    const bool series = circuit.kind == Circuit::Kind::Series;
    for (const Circuit& part : circuit.parts) {
        if (!text.empty())
            text += series ? " * " : " + ";
        const bool grouped = series && part.kind == Circuit::Kind::Parallel;
        text += grouped ? "(" + circuitText(part) + ")" : circuitText(part);
    }
    return text;
}

std::string outputText(const Output& output) {
    switch (output.kind) {
    case OutputKind::Coil:
        return operandText(output.target);
    case OutputKind::SetBit:
        return "SBIT(" + operandText(output.target) + ")";
    case OutputKind::ResetBit:
        return "RBIT(" + operandText(output.target) + ")";
    case OutputKind::Timer: {
        return std::string(timerWord(output.timer)) + "(" + operandText(output.target) + ", " +
               std::string(timeBaseWord(output.base)) + ", " + valueText(output.preset) + ")";
    }
    case OutputKind::Counter: {
        return std::string(counterWord(output.counter)) + "(" + operandText(output.target) + ", " +
               std::string(inputWord(output.input)) + ", " + valueText(output.preset) + ")";
    }
    case OutputKind::Move:
        return "(" + operandText(output.target) + " = " + valueText(output.left) + ")";
    case OutputKind::Formula:
        return "(" + operandText(output.target) + " = " + valueText(output.left) + " " +
               std::string(formulaWord(output.formula)) + " " + valueText(output.right) + ")";
    }
    return {};
}

std::string lineText(const Line& line) {
    std::string text;
    if (const auto* comment = std::get_if<CommentLine>(&line.body))
        return ";" + comment->text;
    if (const auto* declaration = std::get_if<NameDeclaration>(&line.body))
        text = "! " + toString(declaration->variable.address) + "=" + declaration->name;
    else if (const auto* rung = std::get_if<Rung>(&line.body))
        text = outputText(rung->output) +
               (rung->condition ? " = " + circuitText(*rung->condition) : std::string());
    if (line.comment) {
        text += text.size() < kCommentColumn ? std::string(kCommentColumn - text.size(), ' ')
                                             : std::string(" ");
        text += ";" + *line.comment;
    }
    return text;
}

void printLines(std::string& out, const std::vector<Line>& lines) {
    for (const Line& line : lines)
        out += lineText(line) + "\n";
}

} // namespace

std::string printProgram(const Program& program) {
    std::string out = "$target PL110\n";
    if (!program.name.empty())
        out += "$name " + program.name + "\n";
    printLines(out, program.declarations);
    out += "INIT\n";
    printLines(out, program.init);
    out += "MAIN\n";
    printLines(out, program.main);
    return out;
}

std::string printRungLine(const Line& line) {
    return lineText(line);
}

std::string printCondition(const Circuit& circuit) {
    return circuitText(circuit);
}

} // namespace rs::pl110
