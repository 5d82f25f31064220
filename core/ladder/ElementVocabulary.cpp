// SPDX-License-Identifier: GPL-3.0-or-later
#include "ElementVocabulary.h"

#include "LadderToText.h"
#include "lang/Keywords.h"

#include <algorithm>

namespace rs::ladder {

namespace {

using lang::Expr;
using lang::ExprKind;
using lang::Statement;
using lang::StatementKind;

const Expr* exprOf(const ElementNode& node) {
    return std::get_if<Expr>(&node);
}

const Statement* statementOf(const ElementNode& node) {
    return std::get_if<Statement>(&node);
}

Expr contact(const ElementParts& parts, bool negated) {
    Expr expr;
    expr.kind = ExprKind::Contact;
    expr.operand = parts.operand;
    expr.negated = negated;
    return expr;
}

bool isContact(const ElementNode& node, bool negated) {
    const Expr* expr = exprOf(node);
    return expr && expr->kind == ExprKind::Contact && expr->negated == negated;
}

Expr edge(const ElementParts& parts, bool rising, bool negated) {
    Expr expr;
    expr.kind = ExprKind::Edge;
    expr.operand = parts.operand;
    expr.operandNegated = parts.operandNegated;
    expr.risingEdge = rising;
    expr.negated = negated;
    return expr;
}

bool isEdge(const ElementNode& node, bool rising, bool negated) {
    const Expr* expr = exprOf(node);
    return expr && expr->kind == ExprKind::Edge && expr->risingEdge == rising &&
           expr->negated == negated;
}

// A timer keeps the spelling it was written with when that spelling is the kind's (T, IT).
Expr timer(const ElementParts& parts, lang::TimerKind kind, lang::TimerSpelling standard) {
    Expr expr;
    expr.kind = ExprKind::Timer;
    expr.timer = lang::timerKind(parts.timer) == kind ? parts.timer : standard;
    expr.preset = parts.preset;
    expr.negated = parts.negated;
    return expr;
}

bool isTimer(const ElementNode& node, lang::TimerKind kind) {
    const Expr* expr = exprOf(node);
    return expr && expr->kind == ExprKind::Timer && lang::timerKind(expr->timer) == kind;
}

Statement statement(const ElementParts& parts, StatementKind kind) {
    Statement made;
    made.kind = kind;
    made.target = parts.operand;
    return made;
}

bool isStatement(const ElementNode& node, StatementKind kind) {
    const Statement* read = statementOf(node);
    return read && read->kind == kind;
}

const std::vector<ElementKindInfo>& kinds() {
    static const std::vector<ElementKindInfo> all = {
        {ElementKind::NormallyOpen, false, Shape::Contact, OperandRole::Variable, false, false, "C",
         "-| |-", "", "", [](const ElementParts& p) -> ElementNode { return contact(p, false); },
         [](const ElementNode& n) {
             return isContact(n, false);
         }},
        {ElementKind::NormallyClosed, false, Shape::Contact, OperandRole::Variable, false, false,
         "/", "-|/|-", "/", "",
         [](const ElementParts& p) -> ElementNode { return contact(p, true); },
         [](const ElementNode& n) {
             return isContact(n, true);
         }},
        {ElementKind::PositiveEdge, false, Shape::Contact, OperandRole::Variable, false, false, "P",
         "-|P|-", "P", "",
         [](const ElementParts& p) -> ElementNode { return edge(p, true, false); },
         [](const ElementNode& n) {
             return isEdge(n, true, false);
         }},
        {ElementKind::NegativeEdge, false, Shape::Contact, OperandRole::Variable, false, false, "N",
         "-|N|-", "N", "",
         [](const ElementParts& p) -> ElementNode { return edge(p, false, false); },
         [](const ElementNode& n) {
             return isEdge(n, false, false);
         }},
        {ElementKind::NotPositiveEdge, false, Shape::Contact, OperandRole::Variable, false, false,
         "Shift+P", "-|/P|-", "/P", "",
         [](const ElementParts& p) -> ElementNode { return edge(p, true, true); },
         [](const ElementNode& n) {
             return isEdge(n, true, true);
         }},
        {ElementKind::NotNegativeEdge, false, Shape::Contact, OperandRole::Variable, false, false,
         "Shift+N", "-|/N|-", "/N", "",
         [](const ElementParts& p) -> ElementNode { return edge(p, false, true); },
         [](const ElementNode& n) {
             return isEdge(n, false, true);
         }},
        {ElementKind::OnDelayTimer, false, Shape::Box, OperandRole::Preset, false, true, "O",
         "[TON]", "", lang::timerWord(lang::TimerSpelling::TON),
         [](const ElementParts& p) -> ElementNode {
             return timer(p, lang::TimerKind::OnDelay, lang::TimerSpelling::TON);
         },
         [](const ElementNode& n) {
             return isTimer(n, lang::TimerKind::OnDelay);
         }},
        {ElementKind::PulseTimer, false, Shape::Box, OperandRole::Preset, false, true, "U", "[TPS]",
         "", lang::timerWord(lang::TimerSpelling::TPS),
         [](const ElementParts& p) -> ElementNode {
             return timer(p, lang::TimerKind::Pulse, lang::TimerSpelling::TPS);
         },
         [](const ElementNode& n) {
             return isTimer(n, lang::TimerKind::Pulse);
         }},
        {ElementKind::OffDelayTimer, false, Shape::Box, OperandRole::Preset, false, true, "F",
         "[TOF]", "", lang::timerWord(lang::TimerSpelling::TOF),
         [](const ElementParts& p) -> ElementNode {
             return timer(p, lang::TimerKind::OffDelay, lang::TimerSpelling::TOF);
         },
         [](const ElementNode& n) {
             return isTimer(n, lang::TimerKind::OffDelay);
         }},
        {ElementKind::Comparison, false, Shape::Box, OperandRole::Register, true, true, "=", "[>=]",
         "", lang::compareWord(lang::CompareOp::GreaterEqual),
         [](const ElementParts& p) -> ElementNode {
             Expr expr;
             expr.kind = ExprKind::Compare;
             expr.operand = p.operand;
             expr.compare = p.compare;
             expr.right = p.right;
             expr.negated = p.negated;
             return expr;
         },
         [](const ElementNode& n) {
             const Expr* expr = exprOf(n);
             return expr && expr->kind == ExprKind::Compare;
         }},
        {ElementKind::Coil, true, Shape::Coil, OperandRole::Variable, false, false, "L", "-( )", "",
         "", [](const ElementParts& p) -> ElementNode { return statement(p, StatementKind::Coil); },
         [](const ElementNode& n) {
             return isStatement(n, StatementKind::Coil);
         }},
        {ElementKind::Set, true, Shape::Coil, OperandRole::Variable, false, false, "S", "-(S)", "S",
         "", [](const ElementParts& p) -> ElementNode { return statement(p, StatementKind::Set); },
         [](const ElementNode& n) {
             return isStatement(n, StatementKind::Set);
         }},
        {ElementKind::Reset, true, Shape::Coil, OperandRole::Variable, false, false, "R", "-(R)",
         "R", "",
         [](const ElementParts& p) -> ElementNode { return statement(p, StatementKind::Reset); },
         [](const ElementNode& n) {
             return isStatement(n, StatementKind::Reset);
         }},
        {ElementKind::Toggle, true, Shape::Coil, OperandRole::Variable, false, false, "T", "-(T)",
         "T", "",
         [](const ElementParts& p) -> ElementNode { return statement(p, StatementKind::Toggle); },
         [](const ElementNode& n) {
             return isStatement(n, StatementKind::Toggle);
         }},
        {ElementKind::Jump, true, Shape::Coil, OperandRole::Step, false, false, "J", "-(J)", "J",
         "",
         [](const ElementParts& p) -> ElementNode {
             Statement made = statement(p, StatementKind::Jump);
             made.target = {};
             made.relativeJump = p.relativeJump;
             made.jumpStep = p.jumpStep;
             return made;
         },
         [](const ElementNode& n) {
             return isStatement(n, StatementKind::Jump);
         }},
        {ElementKind::SequenceReset, true, Shape::Coil, OperandRole::Sequence, false, false, "Q",
         "-(RS)", "RS", "",
         [](const ElementParts& p) -> ElementNode {
             return statement(p, StatementKind::SequenceReset);
         },
         [](const ElementNode& n) {
             return isStatement(n, StatementKind::SequenceReset);
         }},
        {ElementKind::Arithmetic, true, Shape::Box, OperandRole::TargetRegister, true, false, "+",
         "[+=]", "", lang::assignWord(lang::AssignOp::AddAssign),
         [](const ElementParts& p) -> ElementNode {
             Statement made = statement(p, StatementKind::Assign);
             made.target = {};
             made.assignment = p.assignment;
             made.assignment->target = p.operand;
             return made;
         },
         [](const ElementNode& n) {
             return isStatement(n, StatementKind::Assign);
         }},
    };
    return all;
}

struct PartsReader {
    ElementParts operator()(const Expr& expr) const {
        ElementParts parts;
        parts.operand = expr.operand;
        parts.operandNegated = expr.operandNegated;
        parts.negated = expr.negated;
        parts.timer = expr.timer;
        parts.preset = expr.preset;
        parts.compare = expr.compare;
        parts.right = expr.right;
        return parts;
    }
    ElementParts operator()(const Statement& statement) const {
        ElementParts parts;
        parts.operand = statement.kind == StatementKind::Assign ? statement.assignment->target
                                                                : statement.target;
        parts.assignment = *statement.assignment;
        parts.assignment.target = {};
        parts.relativeJump = statement.relativeJump;
        parts.jumpStep = statement.jumpStep;
        return parts;
    }
};

} // namespace

const std::vector<ElementKindInfo>& elementKinds() {
    return kinds();
}

const ElementKindInfo& infoOf(ElementKind kind) {
    const auto& all = kinds();
    return *std::find_if(all.begin(), all.end(),
                         [kind](const ElementKindInfo& info) { return info.kind == kind; });
}

bool isOutput(ElementKind kind) {
    return infoOf(kind).output;
}

bool isBox(ElementKind kind) {
    return infoOf(kind).shape == Shape::Box;
}

ElementNode makeNode(ElementKind kind, const ElementParts& parts) {
    return infoOf(kind).make(parts);
}

std::optional<ElementKind> kindOf(const ElementNode& node) {
    for (const ElementKindInfo& info : kinds())
        if (info.reads(node))
            return info.kind;
    return std::nullopt;
}

ElementParts partsOf(const ElementNode& node) {
    return std::visit(PartsReader{}, node);
}

ElementKind kindOf(const Element& element) {
    if (const auto* contact = std::get_if<Contact>(&element))
        return contact->kind;
    return *kindOf(ElementNode{toExpr(Circuit::of(element))});
}

ElementKind kindOf(const Output& output) {
    return *kindOf(ElementNode{toStatement(output)});
}

} // namespace rs::ladder
