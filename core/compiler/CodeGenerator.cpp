// SPDX-License-Identifier: GPL-3.0-or-later
#include "CodeGenerator.h"

#include "lang/ElementNumbering.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace rs::compiler {

namespace {

using lang::Expr;
using lang::ExprKind;
using lang::Statement;
using lang::StatementKind;

class Generator {
public:
    explicit Generator(const UnitSetup& unit) : m_unit(unit) {}

    UnitImage run() {
        m_image.station = static_cast<std::uint8_t>(m_unit.station);
        m_image.unitType = static_cast<std::uint8_t>(m_unit.type->type);
        m_image.instructionSet = static_cast<std::uint8_t>(m_unit.instructionSet);

        if (!m_unit.program)
            return std::move(m_image);
        // Code runs in step order; statements keep their file-order numbers
        // (lang::forEachStatement's): each step's first is counted here.
        const auto& steps = m_unit.program->steps;
        std::vector<std::uint32_t> firstNumber;
        std::vector<std::size_t> ordered;
        firstNumber.reserve(steps.size());
        ordered.reserve(steps.size());
        std::uint32_t statements = 0;
        for (std::size_t i = 0; i < steps.size(); ++i) {
            firstNumber.push_back(statements);
            ordered.push_back(i);
            for (const auto& line : steps[i].lines)
                statements += std::holds_alternative<Statement>(line.body) ? 1 : 0;
        }
        const auto key = [&steps](std::size_t i) {
            return std::pair(steps[i].address.sequence, steps[i].address.step);
        };
        std::stable_sort(ordered.begin(), ordered.end(),
                         [&key](std::size_t a, std::size_t b) { return key(a) < key(b); });
        for (std::size_t k = 0; k < ordered.size(); ++k) {
            const std::size_t i = ordered[k];
            // A step written twice is an error the checks report; the code holds its last.
            if (k + 1 < ordered.size() && key(ordered[k + 1]) == key(i))
                continue;
            const auto& step = steps[i];
            StepCode code{static_cast<std::uint8_t>(step.address.sequence),
                          static_cast<std::uint8_t>(step.address.step),
                          static_cast<std::uint32_t>(m_image.code.size()), 0};
            std::uint32_t number = firstNumber[i];
            for (const auto& line : step.lines)
                if (const auto* s = std::get_if<Statement>(&line.body))
                    statement(*s, number++, step.address.step);
                else if (auto call = m_unit.systemCalls.find(&line);
                         call != m_unit.systemCalls.end())
                    systemCall(call->second);
            code.count = static_cast<std::uint32_t>(m_image.code.size()) - code.first;
            m_image.steps.push_back(code);
        }
        // Grown instruction by instruction, the vector held up to twice its
        // code until the image was written.
        m_image.code.shrink_to_fit();
        return std::move(m_image);
    }

private:
    Instruction& emit(Op op, std::uint16_t element) {
        Instruction in;
        in.op = op;
        in.line = static_cast<std::uint32_t>(m_statement->location.line);
        in.column = static_cast<std::uint16_t>(m_statement->location.column);
        in.statement = m_number;
        in.element = element;
        m_image.code.push_back(in);
        return m_image.code.back();
    }

    // The System instruction, then an Argument for each parameter.
    void systemCall(const SystemCall& call) {
        auto emitAt = [&](Op op) -> Instruction& {
            Instruction in;
            in.op = op;
            in.line = static_cast<std::uint32_t>(call.location.line);
            in.column = static_cast<std::uint16_t>(call.location.column);
            in.statement = kNoStatement;
            in.element = lang::kOutputElement;
            m_image.code.push_back(in);
            return m_image.code.back();
        };
        Instruction& system = emitAt(Op::System);
        system.aux = static_cast<std::uint8_t>(call.instruction->id);
        system.slot = static_cast<std::uint16_t>(call.arguments.size());
        for (std::size_t i = 0; i < call.arguments.size(); ++i) {
            const lang::Value& value = call.arguments[i];
            Instruction& argument = emitAt(Op::Argument);
            argument.aux = argumentRole(call.instruction->parameters[i]);
            if (value.operand) {
                argument.operand = value.operand->address;
            } else {
                argument.flags = ConstantOperand;
                argument.constant = static_cast<std::int32_t>(value.constant);
            }
        }
    }

    void statement(const Statement& s, std::uint32_t number, int step) {
        m_statement = &s;
        m_number = number;
        emit(Op::Rung, lang::kOutputElement);
        if (s.condition) {
            lang::PreOrderNumbering<Expr> numbering(*s.condition, lang::partsOf);
            m_numbering = &numbering;
            expression(*s.condition);
            m_numbering = nullptr;
        }
        switch (s.kind) {
        case StatementKind::Coil:
            emit(Op::Coil, lang::kOutputElement).operand = s.target.address;
            break;
        case StatementKind::Set:
            emit(Op::Set, lang::kOutputElement).operand = s.target.address;
            break;
        case StatementKind::Reset:
            emit(Op::Reset, lang::kOutputElement).operand = s.target.address;
            break;
        case StatementKind::Toggle:
            emit(Op::Toggle, lang::kOutputElement).operand = s.target.address;
            break;
        case StatementKind::Jump:
            emit(Op::Jump, lang::kOutputElement).slot =
                static_cast<std::uint16_t>(s.relativeJump ? step + s.jumpStep : s.jumpStep);
            break;
        case StatementKind::SequenceReset:
            emit(Op::SequenceReset, lang::kOutputElement).slot =
                static_cast<std::uint16_t>(s.target.address.index);
            break;
        case StatementKind::Assign:
            assignment(*s.assignment);
            break;
        }
    }

    void load(Op op, const lang::Value& value, std::uint16_t element) {
        Instruction& in = emit(op, element);
        if (value.operand) {
            in.operand = value.operand->address;
        } else {
            in.flags |= ConstantOperand;
            in.constant = static_cast<std::int32_t>(value.constant);
        }
    }

    void assignment(const lang::Assignment& a) {
        ArithOp op = ArithOp::Copy;
        switch (a.op) {
        case lang::AssignOp::Increment:
            op = ArithOp::Increment;
            break;
        case lang::AssignOp::Decrement:
            op = ArithOp::Decrement;
            break;
        case lang::AssignOp::AddAssign:
            op = ArithOp::Add;
            break;
        case lang::AssignOp::SubAssign:
            op = ArithOp::Sub;
            break;
        case lang::AssignOp::MulAssign:
            op = ArithOp::Mul;
            break;
        case lang::AssignOp::DivAssign:
            op = ArithOp::Div;
            break;
        case lang::AssignOp::Copy:
            op = ArithOp::Copy;
            break;
        case lang::AssignOp::Binary:
            static constexpr ArithOp binary[] = {ArithOp::AddAB, ArithOp::SubAB, ArithOp::MulAB,
                                                 ArithOp::DivAB};
            op = binary[static_cast<int>(a.binary)];
            break;
        }
        if (op != ArithOp::Increment && op != ArithOp::Decrement)
            load(Op::LoadA, a.left, 0);
        if (a.op == lang::AssignOp::Binary)
            load(Op::LoadB, a.right, 0);
        Instruction& in = emit(Op::Arith, 0);
        in.aux = static_cast<std::uint8_t>(op);
        in.operand = a.target.address;
    }

    void expression(const Expr& e) {
        const std::uint16_t element = m_numbering->number(e);
        const std::uint8_t negated = e.negated ? Negated : 0;
        switch (e.kind) {
        case ExprKind::And:
            for (const auto& child : e.children)
                expression(child);
            return;
        case ExprKind::Or:
            emit(Op::BranchOpen, element);
            for (std::size_t i = 0; i < e.children.size(); ++i) {
                if (i)
                    emit(Op::BranchNext, element);
                expression(e.children[i]);
            }
            emit(Op::BranchClose, element);
            return;
        case ExprKind::Contact: {
            Instruction& in = emit(Op::Contact, element);
            in.flags = negated;
            in.operand = e.operand.address;
            return;
        }
        case ExprKind::Edge: {
            Instruction& in = emit(Op::Edge, element);
            in.flags = static_cast<std::uint8_t>(negated | (e.operandNegated ? OperandNegated : 0) |
                                                 (e.risingEdge ? Rising : 0));
            in.slot = m_image.edges++;
            in.operand = e.operand.address;
            return;
        }
        case ExprKind::Timer: {
            Instruction& in = emit(Op::Timer, element);
            in.flags = negated;
            in.aux = static_cast<std::uint8_t>(lang::timerKind(e.timer));
            in.slot = m_image.timers++;
            if (e.preset.registerOperand) {
                in.operand = e.preset.registerOperand->address;
            } else {
                in.flags |= ConstantOperand;
                in.constant = e.preset.hundredths;
            }
            return;
        }
        case ExprKind::Compare: {
            Instruction& left = emit(Op::LoadA, element);
            left.operand = e.operand.address;
            load(Op::LoadB, e.right, element);
            Instruction& in = emit(Op::Compare, element);
            in.flags = negated;
            in.aux = static_cast<std::uint8_t>(e.compare);
            return;
        }
        }
    }

    const UnitSetup& m_unit;
    UnitImage m_image;
    const Statement* m_statement = nullptr;
    std::uint32_t m_number = 0;
    lang::PreOrderNumbering<Expr>* m_numbering = nullptr;
};

} // namespace

UnitImage generateCode(const UnitSetup& unit) {
    return Generator(unit).run();
}

} // namespace rs::compiler
