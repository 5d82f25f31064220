// SPDX-License-Identifier: GPL-3.0-or-later
#include "Unrolling.h"

#include <utility>

namespace rs::prove {

Unrolling::Unrolling(const ScanModel& model, bool freeStart, const std::vector<Lit>& roots)
    : m_model(model), m_freeStart(freeStart), m_solver(std::make_unique<CaDiCaL::Solver>()) {
    m_place.assign(model.graph().nodes(), -1);
    if (roots.empty()) {
        for (std::uint32_t node = 0; node < model.graph().nodes(); ++node)
            m_place[node] = static_cast<std::int32_t>(node);
        m_coneSize = model.graph().nodes();
    } else {
        for (std::uint32_t node : model.cone(roots))
            m_place[node] = static_cast<std::int32_t>(m_coneSize++);
    }
    m_true = newVariable();
    addClause({m_true});
}

Unrolling::~Unrolling() = default;

void Unrolling::addClause(std::initializer_list<int> literals) {
    for (int literal : literals)
        m_solver->add(literal);
    m_solver->add(0);
    ++m_clauses;
}

void Unrolling::addClause(const std::vector<int>& literals) {
    for (int literal : literals)
        m_solver->add(literal);
    m_solver->add(0);
    ++m_clauses;
}

int Unrolling::literal(Lit a, int frame) {
    const AndGraph& graph = m_model.graph();
    if (m_frames.size() <= static_cast<std::size_t>(frame))
        m_frames.resize(static_cast<std::size_t>(frame) + 1);
    auto slot = [&](std::uint32_t node, int f) -> int& {
        auto& map = m_frames[static_cast<std::size_t>(f)];
        if (map.empty())
            map.assign(m_coneSize, 0);
        return map[static_cast<std::size_t>(m_place[node])];
    };
    // Depth first without recursion: a node is encoded once its fanins are.
    std::vector<std::pair<std::uint32_t, int>> stack{{nodeOf(a), frame}};
    while (!stack.empty()) {
        const auto [node, f] = stack.back();
        int& variable = slot(node, f);
        if (variable != 0) {
            stack.pop_back();
            continue;
        }
        if (node == 0) {
            variable = -m_true;
            stack.pop_back();
            continue;
        }
        if (graph.isVariable(node)) {
            const int state = m_model.stateOf(node);
            if (state < 0 || (f == 0 && m_freeStart)) {
                variable = newVariable();
            } else if (f == 0) {
                variable =
                    m_model.state()[static_cast<std::size_t>(state)].initial ? m_true : -m_true;
            } else {
                const Lit next = m_model.state()[static_cast<std::size_t>(state)].next;
                const int known = slot(nodeOf(next), f - 1);
                if (known == 0) {
                    stack.emplace_back(nodeOf(next), f - 1);
                    continue;
                }
                slot(node, f) = isNegated(next) ? -known : known;
            }
            stack.pop_back();
            continue;
        }
        const Lit left = graph.left(node);
        const Lit right = graph.right(node);
        const int l = slot(nodeOf(left), f);
        const int r = slot(nodeOf(right), f);
        if (l == 0 || r == 0) {
            if (l == 0)
                stack.emplace_back(nodeOf(left), f);
            if (r == 0)
                stack.emplace_back(nodeOf(right), f);
            continue;
        }
        const int x = newVariable();
        const int sl = isNegated(left) ? -l : l;
        const int sr = isNegated(right) ? -r : r;
        addClause({-x, sl});
        addClause({-x, sr});
        addClause({x, -sl, -sr});
        slot(node, f) = x;
        stack.pop_back();
    }
    const int v = slot(nodeOf(a), frame);
    return isNegated(a) ? -v : v;
}

int Unrolling::solve(const std::vector<int>& assumptions) {
    for (int literal : assumptions)
        m_solver->assume(literal);
    return m_solver->solve();
}

bool Unrolling::value(Lit a, int frame) {
    // Only what is encoded has a value; anything else is outside every cone
    // the solver saw, and any value does.
    if (nodeOf(a) == 0)
        return a == kTrue;
    if (static_cast<std::size_t>(frame) >= m_frames.size() ||
        m_frames[static_cast<std::size_t>(frame)].empty() || m_place[nodeOf(a)] < 0)
        return false;
    const int v =
        m_frames[static_cast<std::size_t>(frame)][static_cast<std::size_t>(m_place[nodeOf(a)])];
    if (v == 0)
        return false;
    return (m_solver->val(v) > 0) != isNegated(a);
}

std::int64_t Unrolling::value(const Word& word, int frame) {
    std::uint64_t bits = 0;
    for (int i = 0; i < 64; ++i) {
        const Lit bit = i < word.width() ? word.bits[static_cast<std::size_t>(i)] : word.sign();
        if (value(bit, frame))
            bits |= std::uint64_t{1} << i;
    }
    return static_cast<std::int64_t>(bits);
}

} // namespace rs::prove
