// SPDX-License-Identifier: GPL-3.0-or-later
#include "AndGraph.h"

#include <algorithm>
#include <utility>

namespace rs::prove {

AndGraph::AndGraph() {
    m_fanin.push_back({0, 0});
}

Lit AndGraph::variable() {
    m_fanin.push_back({0, 0});
    return (nodes() - 1) * 2;
}

namespace {

std::size_t slotOf(Lit a, Lit b, std::size_t mask) {
    std::uint64_t key = (std::uint64_t{a} << 32) | b;
    key *= 0x9E3779B97F4A7C15ull; // Fibonacci hashing: the high bits mix every input bit
    return static_cast<std::size_t>(key >> 32) & mask;
}

} // namespace

Lit AndGraph::conj(Lit a, Lit b) {
    if (a > b)
        std::swap(a, b);
    if (a == kFalse || a == negate(b))
        return kFalse;
    if (a == kTrue || a == b)
        return b;
    const std::size_t mask = m_table.size() - 1;
    std::size_t slot = slotOf(a, b, mask);
    while (const std::uint32_t node = m_table[slot]) {
        if (m_fanin[node].left == a && m_fanin[node].right == b)
            return node * 2;
        slot = (slot + 1) & mask;
    }
    const std::uint32_t node = nodes();
    m_fanin.push_back({a, b});
    m_table[slot] = node;
    if (++m_gates * 2 > m_table.size())
        grow();
    return node * 2;
}

void AndGraph::grow() {
    std::vector<std::uint32_t> table(m_table.size() * 2, 0);
    const std::size_t mask = table.size() - 1;
    for (std::uint32_t node : m_table)
        if (node) {
            std::size_t slot = slotOf(m_fanin[node].left, m_fanin[node].right, mask);
            while (table[slot])
                slot = (slot + 1) & mask;
            table[slot] = node;
        }
    m_table = std::move(table);
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

void AndGraph::evaluate(std::vector<std::uint64_t>& values,
                        const std::vector<std::uint32_t>& gates) const {
    values.resize(m_fanin.size());
    values[0] = 0;
    for (std::uint32_t node : gates)
        values[node] = value(values, m_fanin[node].left) & value(values, m_fanin[node].right);
}

} // namespace rs::prove
