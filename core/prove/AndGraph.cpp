// SPDX-License-Identifier: GPL-3.0-or-later
#include "AndGraph.h"

#include <utility>

namespace rs::prove {

AndGraph::AndGraph() {
    m_fanin.push_back({0, 0});
}

Lit AndGraph::variable() {
    m_fanin.push_back({0, 0});
    return (nodes() - 1) * 2;
}

Lit AndGraph::conj(Lit a, Lit b) {
    if (a > b)
        std::swap(a, b);
    if (a == kFalse || a == negate(b))
        return kFalse;
    if (a == kTrue || a == b)
        return b;
    const std::uint64_t key = (std::uint64_t{a} << 32) | b;
    const auto [at, added] = m_gates.try_emplace(key, nodes());
    if (added)
        m_fanin.push_back({a, b});
    return at->second * 2;
}

Lit AndGraph::exclusive(Lit a, Lit b) {
    if (a == kFalse)
        return b;
    if (b == kFalse)
        return a;
    if (a == kTrue)
        return negate(b);
    if (b == kTrue)
        return negate(a);
    if (a == b)
        return kFalse;
    if (a == negate(b))
        return kTrue;
    return disj(conj(a, negate(b)), conj(negate(a), b));
}

Lit AndGraph::choose(Lit c, Lit a, Lit b) {
    if (c == kTrue || a == b)
        return a;
    if (c == kFalse)
        return b;
    return disj(conj(c, a), conj(negate(c), b));
}

void AndGraph::evaluate(std::vector<std::uint64_t>& values, std::uint32_t from) const {
    values.resize(m_fanin.size());
    values[0] = 0;
    for (std::uint32_t node = from; node < nodes(); ++node)
        if (m_fanin[node].left != 0)
            values[node] = value(values, m_fanin[node].left) & value(values, m_fanin[node].right);
}

} // namespace rs::prove
