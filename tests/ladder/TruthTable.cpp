// SPDX-License-Identifier: GPL-3.0-or-later
#include "TruthTable.h"

#include "lang/Printer.h"

#include <map>
#include <stdexcept>

namespace rs::test {

using namespace rs::lang;
using ladder::Circuit;

namespace {

std::string bitAtom(const Operand& operand) {
    return "bit " + printOperand(operand);
}

std::string compareAtom(const Operand& left, CompareOp op, const Value& right) {
    Expr e;
    e.kind = ExprKind::Compare;
    e.operand = left;
    e.compare = op;
    e.right = right;
    return "compare " + printExpression(e);
}

std::string occurrenceAtom(const char* kind, int number) {
    return std::string(kind) + " #" + std::to_string(number);
}

bool timerOutput(TimerSpelling spelling, bool input, bool state) {
    return timerKind(spelling) == TimerKind::OffDelay ? input || state : input && state;
}

// One evaluation: atoms are looked up by name; occurrences are counted in
// pre-order as the walk meets them.
class Evaluation {
public:
    Evaluation(const std::map<std::string, int>& index, unsigned row)
        : m_index(index), m_row(row) {}

    bool atom(const std::string& name) const { return (m_row >> m_index.at(name)) & 1U; }
    bool nextEdge() { return atom(occurrenceAtom("edge", m_edges++)); }
    bool nextTimer() { return atom(occurrenceAtom("timer", m_timers++)); }

private:
    const std::map<std::string, int>& m_index;
    unsigned m_row;
    int m_edges = 0;
    int m_timers = 0;
};

// ----- the expression

void collect(const Expr& e, std::set<std::string>& atoms, int& edges, int& timers) {
    switch (e.kind) {
    case ExprKind::And:
    case ExprKind::Or:
        for (const auto& child : e.children)
            collect(child, atoms, edges, timers);
        return;
    case ExprKind::Contact:
        atoms.insert(bitAtom(e.operand));
        return;
    case ExprKind::Edge:
        atoms.insert(occurrenceAtom("edge", edges++));
        return;
    case ExprKind::Timer:
        atoms.insert(occurrenceAtom("timer", timers++));
        return;
    case ExprKind::Compare:
        atoms.insert(compareAtom(e.operand, e.compare, e.right));
        return;
    }
}

bool power(const Expr& e, bool input, Evaluation& at) {
    switch (e.kind) {
    case ExprKind::And: {
        bool p = input;
        for (const auto& child : e.children)
            p = power(child, p, at);
        return p;
    }
    case ExprKind::Or: {
        bool any = false;
        for (const auto& child : e.children)
            any = power(child, input, at) || any; // every child is walked: occurrences count
        return any;
    }
    case ExprKind::Contact:
        return input && (at.atom(bitAtom(e.operand)) != e.negated);
    case ExprKind::Edge: {
        const bool seen = at.nextEdge(); // counted even where no power reaches it
        return input && (seen != e.negated);
    }
    case ExprKind::Compare:
        return input && (at.atom(compareAtom(e.operand, e.compare, e.right)) != e.negated);
    case ExprKind::Timer: {
        const bool out = timerOutput(e.timer, input, at.nextTimer());
        return e.negated ? input && !out : out;
    }
    }
    return false;
}

bool algebra(const Expr& e, Evaluation& at) {
    switch (e.kind) {
    case ExprKind::And: {
        bool all = true;
        for (const auto& child : e.children)
            all = algebra(child, at) && all;
        return all;
    }
    case ExprKind::Or: {
        bool any = false;
        for (const auto& child : e.children)
            any = algebra(child, at) || any;
        return any;
    }
    case ExprKind::Contact:
        return at.atom(bitAtom(e.operand)) != e.negated;
    case ExprKind::Edge:
        return at.nextEdge() != e.negated;
    case ExprKind::Compare:
        return at.atom(compareAtom(e.operand, e.compare, e.right)) != e.negated;
    case ExprKind::Timer:
        break;
    }
    throw std::logic_error("the algebra table is for conditions without timers");
}

// ----- the circuit

void collect(const Circuit& c, std::set<std::string>& atoms, int& edges, int& timers) {
    if (!c.isElement()) {
        for (const auto& part : c.parts)
            collect(part, atoms, edges, timers);
        return;
    }
    if (const auto* contact = std::get_if<ladder::Contact>(&c.element)) {
        if (ladder::isEdge(contact->kind))
            atoms.insert(occurrenceAtom("edge", edges++));
        else
            atoms.insert(bitAtom(contact->operand));
    } else if (std::holds_alternative<ladder::TimerBox>(c.element)) {
        atoms.insert(occurrenceAtom("timer", timers++));
    } else {
        const auto& box = std::get<ladder::ComparisonBox>(c.element);
        atoms.insert(compareAtom(box.left, box.op, box.right));
    }
}

bool power(const Circuit& c, bool input, Evaluation& at) {
    switch (c.kind) {
    case Circuit::Kind::Series: {
        bool p = input;
        for (const auto& part : c.parts)
            p = power(part, p, at);
        return p;
    }
    case Circuit::Kind::Parallel: {
        bool any = false;
        for (const auto& part : c.parts)
            any = power(part, input, at) || any;
        return any;
    }
    case Circuit::Kind::Element:
        break;
    }
    if (const auto* contact = std::get_if<ladder::Contact>(&c.element)) {
        using ladder::ElementKind;
        switch (contact->kind) {
        case ElementKind::NormallyOpen:
            return input && at.atom(bitAtom(contact->operand));
        case ElementKind::NormallyClosed:
            return input && !at.atom(bitAtom(contact->operand));
        default: // an edge, the only other kind a contact has
            break;
        }
        const bool seen = at.nextEdge(); // counted even where no power reaches it
        const bool inverted = contact->kind == ElementKind::NotPositiveEdge ||
                              contact->kind == ElementKind::NotNegativeEdge;
        return input && (seen != inverted);
    }
    if (const auto* timer = std::get_if<ladder::TimerBox>(&c.element)) {
        const bool out = timerOutput(timer->spelling, input, at.nextTimer());
        return timer->negated ? input && !out : out;
    }
    const auto& box = std::get<ladder::ComparisonBox>(c.element);
    return input && (at.atom(compareAtom(box.left, box.op, box.right)) != box.negated);
}

template <typename Tree, typename Evaluate>
TruthTable tabulate(const Tree& tree, Evaluate evaluate) {
    TruthTable table;
    int edges = 0;
    int timers = 0;
    collect(tree, table.atoms, edges, timers);
    if (table.atoms.size() > kMostAtoms)
        return table;
    std::map<std::string, int> index;
    for (const auto& atom : table.atoms)
        index.emplace(atom, static_cast<int>(index.size()));
    const unsigned rows = 1U << table.atoms.size();
    for (unsigned row = 0; row < rows; ++row) {
        Evaluation at(index, row);
        table.rows.push_back(evaluate(tree, at));
    }
    return table;
}

} // namespace

TruthTable truthTable(const Expr& expr) {
    return tabulate(expr, [](const Expr& e, Evaluation& at) { return power(e, true, at); });
}

TruthTable truthTable(const Circuit& circuit) {
    return tabulate(circuit, [](const Circuit& c, Evaluation& at) { return power(c, true, at); });
}

TruthTable algebraTable(const Expr& expr) {
    return tabulate(expr, [](const Expr& e, Evaluation& at) { return algebra(e, at); });
}

} // namespace rs::test
