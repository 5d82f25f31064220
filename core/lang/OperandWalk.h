// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Ast.h"

#include <concepts>
#include <type_traits>

namespace rs::lang {

// Calls `visit` on every operand a statement writes or reads: its target,
// an assignment's target and values, and every operand of its condition
// (contacts, edges, comparisons and their values, a timer's register
// preset), in that order. Const or not, as the statement is.
template <typename E, typename Visit>
requires std::same_as<std::remove_const_t<E>, Expr>
void forEachOperand(E& expr, Visit&& visit) {
    for (auto& child : expr.children)
        forEachOperand(child, visit);
    visit(expr.operand);
    if (expr.right.operand)
        visit(*expr.right.operand);
    if (expr.preset.registerOperand)
        visit(*expr.preset.registerOperand);
}

template <typename S, typename Visit>
requires std::same_as<std::remove_const_t<S>, Statement>
void forEachOperand(S& statement, Visit&& visit) {
    visit(statement.target);
    if (statement.assignment.held()) { // else it has no operands
        visit(statement.assignment->target);
        for (auto* value : {&statement.assignment->left, &statement.assignment->right})
            if (value->operand)
                visit(*value->operand);
    }
    if (statement.condition)
        forEachOperand(*statement.condition, visit);
}

} // namespace rs::lang
