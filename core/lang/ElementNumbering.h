// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Ast.h"

#include <compare>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace rs::lang {

// How a unit's statements and the elements of their conditions are numbered.
// The compiler writes these numbers into every instruction, the simulator
// marks conduction by them, the ladder layout puts them on every drawn
// element, and diagnostics are placed on elements by them; so the rule is
// written once, here.
//
// - Statements: in file order across the unit's steps, from 0.
// - Elements: the nodes of a statement's condition in pre-order from 1,
//   groups (And, Or; series, parallel) included. 0 is the statement's output.
struct ElementNumber {
    std::uint32_t statement = 0;
    std::uint16_t element = 0;
    friend auto operator<=>(const ElementNumber&, const ElementNumber&) = default;
};

inline constexpr std::uint16_t kOutputElement = 0;

// Calls visit(step, statement, number) for every statement of the unit in
// file order.
template <typename Visit> void forEachStatement(const UnitProgram& unit, Visit&& visit) {
    std::uint32_t number = 0;
    for (const auto& step : unit.steps)
        for (const auto& line : step.lines)
            if (const auto* statement = std::get_if<Statement>(&line.body))
                visit(step, *statement, number++);
}

// The pre-order numbering of a condition tree whose groups hold their parts
// in `partsOf(node)`: works for the syntax tree (Expr) and the ladder's
// circuits alike. The code that walks the tree asks for each node's number
// as it reaches it, in pre-order; reaching another node than the rule says
// is a bug in that walk, and throws.
template <typename Node> class PreOrderNumbering {
public:
    template <typename PartsOf> PreOrderNumbering(const Node& root, PartsOf partsOf) {
        add(root, partsOf);
    }

    // The number of the node the walk has reached.
    std::uint16_t number(const Node& node) {
        if (m_next >= m_nodes.size() || m_nodes[m_next] != &node)
            throw std::logic_error("condition walked out of pre-order");
        return static_cast<std::uint16_t>(++m_next);
    }

    // Nodes in pre-order: node i has number i + 1.
    const std::vector<const Node*>& nodes() const { return m_nodes; }

private:
    template <typename PartsOf> void add(const Node& node, PartsOf partsOf) {
        m_nodes.push_back(&node);
        for (const auto& part : partsOf(node))
            add(part, partsOf);
    }

    std::vector<const Node*> m_nodes;
    std::size_t m_next = 0;
};

inline const std::vector<Expr>& partsOf(const Expr& expr) {
    return expr.children;
}

// The element a message at (line, column) of the unit's text concerns: the
// statement on that line, and the last element of its condition that starts
// at or before the column (the output, 0, when none does). Nothing when no
// statement is on that line.
std::optional<ElementNumber> elementAt(const UnitProgram& unit, int line, int column);

} // namespace rs::lang
