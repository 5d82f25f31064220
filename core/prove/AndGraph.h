// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <vector>

// An and-inverter graph: the prover's circuits, built once per property set
// and handed to the SAT solver frame by frame (docs/prove.md, "The model").
// Constants fold and equal gates are shared as they are made, so a program's
// constant operands cost nothing.
namespace rs::prove {

// A literal: node * 2, plus 1 when negated. Node 0 is the constant false.
using Lit = std::uint32_t;
inline constexpr Lit kFalse = 0;
inline constexpr Lit kTrue = 1;
constexpr Lit negate(Lit a) {
    return a ^ 1u;
}
constexpr std::uint32_t nodeOf(Lit a) {
    return a >> 1;
}
constexpr bool isNegated(Lit a) {
    return a & 1u;
}
constexpr Lit literalOf(bool value) {
    return value ? kTrue : kFalse;
}

class AndGraph {
public:
    AndGraph();

    // A free variable: a state bit's current value or an input of a scan.
    Lit variable();
    Lit conj(Lit a, Lit b);
    Lit disj(Lit a, Lit b) { return negate(conj(negate(a), negate(b))); }
    Lit exclusive(Lit a, Lit b);
    Lit equal(Lit a, Lit b) { return negate(exclusive(a, b)); }
    // c ? a : b
    Lit choose(Lit c, Lit a, Lit b);

    std::uint32_t nodes() const { return static_cast<std::uint32_t>(m_fanin.size()); }
    bool isVariable(std::uint32_t node) const { return node != 0 && m_fanin[node].left == 0; }
    Lit left(std::uint32_t node) const { return m_fanin[node].left; }
    Lit right(std::uint32_t node) const { return m_fanin[node].right; }

    // 64 evaluations at once: `values` holds a word per node, variables set
    // by the caller; every gate from `from` on is computed.
    void evaluate(std::vector<std::uint64_t>& values, std::uint32_t from = 1) const;
    // Only these gates, in ascending order (a gate's fanins come before it).
    void evaluate(std::vector<std::uint64_t>& values,
                  const std::vector<std::uint32_t>& gates) const;
    static std::uint64_t value(const std::vector<std::uint64_t>& values, Lit a) {
        return values[nodeOf(a)] ^ (isNegated(a) ? ~std::uint64_t{0} : 0);
    }

private:
    // A variable has left == 0 (a gate's fanins are never the constant: it folds).
    struct Fanin {
        Lit left;
        Lit right;
    };
    void grow();

    std::vector<Fanin> m_fanin;
    // Gates by their fanins: open addressing, node numbers, 0 for a free slot.
    std::vector<std::uint32_t> m_table = std::vector<std::uint32_t>(1024, 0);
    std::uint32_t m_gates = 0;
};

} // namespace rs::prove
