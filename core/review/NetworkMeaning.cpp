// SPDX-License-Identifier: GPL-3.0-or-later
#include "NetworkMeaning.h"

#include "compiler/SystemCall.h"
#include "lang/Printer.h"

namespace rs::review {

namespace {

void unname(lang::Operand& operand) {
    operand.name = {};
}

void unname(lang::Value& value) {
    if (value.operand)
        unname(*value.operand);
}

lang::TimerSpelling oneSpelling(lang::TimerSpelling spelling) {
    switch (lang::timerKind(spelling)) {
    case lang::TimerKind::OnDelay:
        return lang::TimerSpelling::TON;
    case lang::TimerKind::Pulse:
        return lang::TimerSpelling::TPS;
    case lang::TimerKind::OffDelay:
        return lang::TimerSpelling::TOF;
    }
    return spelling;
}

void unname(lang::Expr& expr) {
    unname(expr.operand);
    unname(expr.right);
    if (expr.preset.registerOperand)
        unname(*expr.preset.registerOperand);
    if (expr.kind == lang::ExprKind::Timer)
        expr.timer = oneSpelling(expr.timer);
    for (auto& child : expr.children)
        unname(child);
}

std::string meaning(lang::Statement statement) {
    unname(statement.target);
    unname(statement.assignment->target);
    unname(statement.assignment->left);
    unname(statement.assignment->right);
    if (statement.condition)
        unname(*statement.condition);
    return lang::printStatement(statement);
}

std::string meaning(const compiler::SystemCall& call) {
    std::string text = "system " + std::string(call.instruction->name);
    for (lang::Value argument : call.arguments) {
        unname(argument);
        text += ' ' + lang::printValue(argument);
    }
    return text;
}

} // namespace

std::string networkMeaning(const lang::Document& document, int station,
                           const project::Network& network) {
    std::string text;
    for (const lang::Line* line : network.lines) {
        if (const auto* statement = std::get_if<lang::Statement>(&line->body)) {
            text += meaning(*statement) + '\n';
        } else if (compiler::isSystemRecord(*line)) {
            lang::Diagnostics ignored; // reading the project reports them
            if (const auto call = compiler::readSystemCall(document, station, *line, ignored))
                text += meaning(*call) + '\n';
            else
                text += "system call in error\n";
        }
    }
    return text;
}

} // namespace rs::review
