// SPDX-License-Identifier: GPL-3.0-or-later
#include "Unrolling.h"

#include <utility>

namespace rs::prove {

Unrolling::Unrolling(const ScanModel& model, bool freeStart)
    : m_model(model), m_freeStart(freeStart), m_solver(std::make_unique<CaDiCaL::Solver>()) {
    m_stateOf.assign(model.graph().nodes(), -1);
    for (std::size_t i = 0; i < model.state().size(); ++i)
        m_stateOf[nodeOf(model.state()[i].current)] = static_cast<int>(i);
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
    // Depth first without recursion: a node is encoded once its fanins are.
    std::vector<std::pair<std::uint32_t, int>> stack{{nodeOf(a), frame}};
    while (!stack.empty()) {
        const auto [node, f] = stack.back();
        auto& map = m_frames[static_cast<std::size_t>(f)];
        if (map.empty())
            map.assign(graph.nodes(), 0);
        if (map[node] != 0) {
            stack.pop_back();
            continue;
        }
        if (node == 0) {
            map[node] = -m_true;
            stack.pop_back();
            continue;
        }
        if (graph.isVariable(node)) {
            const int state = m_stateOf[node];
            if (state < 0 || (f == 0 && m_freeStart)) {
                map[node] = newVariable();
            } else if (f == 0) {
                map[node] =
                    m_model.state()[static_cast<std::size_t>(state)].initial ? m_true : -m_true;
            } else {
                const Lit next = m_model.state()[static_cast<std::size_t>(state)].next;
                auto& previous = m_frames[static_cast<std::size_t>(f - 1)];
                if (previous.empty())
                    previous.assign(graph.nodes(), 0);
                const int known = previous[nodeOf(next)];
                if (known == 0) {
                    stack.emplace_back(nodeOf(next), f - 1);
                    continue;
                }
                map[node] = isNegated(next) ? -known : known;
            }
            stack.pop_back();
            continue;
        }
        const Lit left = graph.left(node);
        const Lit right = graph.right(node);
        const int l = map[nodeOf(left)];
        const int r = map[nodeOf(right)];
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
        map[node] = x;
        stack.pop_back();
    }
    const int v = m_frames[static_cast<std::size_t>(frame)][nodeOf(a)];
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
        m_frames[static_cast<std::size_t>(frame)].empty())
        return false;
    const int v = m_frames[static_cast<std::size_t>(frame)][nodeOf(a)];
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
