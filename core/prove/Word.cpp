// SPDX-License-Identifier: GPL-3.0-or-later
#include "Word.h"

#include <algorithm>

namespace rs::prove {

Word WordBuilder::constant(std::int64_t value, int width) const {
    if (width == 0) {
        width = 1;
        while (width < 64 && (value < -(std::int64_t{1} << (width - 1)) ||
                              value >= (std::int64_t{1} << (width - 1))))
            ++width;
    }
    Word word;
    for (int i = 0; i < width; ++i)
        word.bits.push_back(literalOf(((value >> std::min(i, 63)) & 1) != 0));
    return word;
}

Word WordBuilder::variables(int width) {
    Word word;
    for (int i = 0; i < width; ++i)
        word.bits.push_back(m_graph.variable());
    return word;
}

Word WordBuilder::extended(const Word& a, int width) const {
    Word word;
    for (int i = 0; i < width; ++i)
        word.bits.push_back(i < a.width() ? a.bits[static_cast<std::size_t>(i)] : a.sign());
    return word;
}

Word WordBuilder::trimmed(Word a) {
    while (a.width() > 1 && a.bits[a.bits.size() - 1] == a.bits[a.bits.size() - 2])
        a.bits.pop_back();
    return a;
}

Word WordBuilder::unsignedAdd(const Word& a, const Word& b, Lit carry, int width) {
    const Word x = extended(a, width);
    const Word y = extended(b, width);
    Word sum;
    for (int i = 0; i < width; ++i) {
        const Lit p = x.bits[static_cast<std::size_t>(i)];
        const Lit q = y.bits[static_cast<std::size_t>(i)];
        const Lit half = m_graph.exclusive(p, q);
        sum.bits.push_back(m_graph.exclusive(half, carry));
        carry = m_graph.disj(m_graph.conj(p, q), m_graph.conj(half, carry));
    }
    return sum;
}

Word WordBuilder::add(const Word& a, const Word& b) {
    return trimmed(unsignedAdd(a, b, kFalse, std::max(a.width(), b.width()) + 1));
}

Word WordBuilder::subtract(const Word& a, const Word& b) {
    const int width = std::max(a.width(), b.width()) + 1;
    Word notB = extended(b, width);
    for (Lit& bit : notB.bits)
        bit = negate(bit);
    return trimmed(unsignedAdd(a, notB, kTrue, width));
}

Word WordBuilder::negated(const Word& a) {
    return subtract(constant(0, 1), a);
}

Word WordBuilder::multiply(const Word& a, const Word& b) {
    const int width = a.width() + b.width();
    const Word x = extended(a, width);
    const Word y = extended(b, width);
    Word product = constant(0, width);
    for (int i = 0; i < width; ++i) {
        const Lit bit = y.bits[static_cast<std::size_t>(i)];
        if (bit == kFalse)
            continue;
        Word partial = constant(0, width);
        for (int j = 0; i + j < width; ++j)
            partial.bits[static_cast<std::size_t>(i + j)] =
                m_graph.conj(bit, x.bits[static_cast<std::size_t>(j)]);
        product = unsignedAdd(product, partial, kFalse, width);
    }
    return trimmed(product);
}

void WordBuilder::divide(const Word& dividend, const Word& divisor, Word& quotient,
                         Word& remainder) {
    // Magnitudes, one bit wider than the operands so that -2^(n-1) has one.
    const int width = std::max(dividend.width(), divisor.width()) + 1;
    const Lit negativeDividend = dividend.sign();
    const Lit negativeDivisor = divisor.sign();
    const Word n = extended(choose(negativeDividend, negated(dividend), dividend), width);
    const Word d = extended(choose(negativeDivisor, negated(divisor), divisor), width);
    // Restoring division, most significant bit first.
    Word rest = constant(0, width + 1);
    Word q = constant(0, width);
    for (int i = width - 1; i >= 0; --i) {
        Word shifted;
        shifted.bits.push_back(n.bits[static_cast<std::size_t>(i)]);
        for (int j = 0; j < width; ++j)
            shifted.bits.push_back(rest.bits[static_cast<std::size_t>(j)]);
        // shifted - d, unsigned: both as non-negative signed numbers one bit wider.
        Word wide = shifted;
        wide.bits.push_back(kFalse);
        Word divisorWide = d;
        divisorWide.bits.push_back(kFalse);
        const Word difference = extended(subtract(wide, divisorWide), width + 2);
        const Lit fits = negate(difference.sign());
        q.bits[static_cast<std::size_t>(i)] = fits;
        Word next;
        for (int j = 0; j <= width; ++j)
            next.bits.push_back(m_graph.choose(fits, difference.bits[static_cast<std::size_t>(j)],
                                               shifted.bits[static_cast<std::size_t>(j)]));
        rest = next;
    }
    q.bits.push_back(kFalse);
    rest.bits.push_back(kFalse);
    quotient = trimmed(choose(m_graph.exclusive(negativeDividend, negativeDivisor), negated(q), q));
    remainder = trimmed(choose(negativeDividend, negated(rest), rest));
}

Lit WordBuilder::equal(const Word& a, const Word& b) {
    const int width = std::max(a.width(), b.width());
    const Word x = extended(a, width);
    const Word y = extended(b, width);
    Lit all = kTrue;
    for (int i = 0; i < width; ++i)
        all = m_graph.conj(all, m_graph.equal(x.bits[static_cast<std::size_t>(i)],
                                              y.bits[static_cast<std::size_t>(i)]));
    return all;
}

Lit WordBuilder::less(const Word& a, const Word& b) {
    return subtract(a, b).sign();
}

Lit WordBuilder::isZero(const Word& a) {
    Lit any = kFalse;
    for (Lit bit : a.bits)
        any = m_graph.disj(any, bit);
    return negate(any);
}

Word WordBuilder::choose(Lit c, const Word& a, const Word& b) {
    const int width = std::max(a.width(), b.width());
    const Word x = extended(a, width);
    const Word y = extended(b, width);
    Word word;
    for (int i = 0; i < width; ++i)
        word.bits.push_back(m_graph.choose(c, x.bits[static_cast<std::size_t>(i)],
                                           y.bits[static_cast<std::size_t>(i)]));
    return trimmed(word);
}

Word WordBuilder::saturated(const Word& a, std::int64_t low, std::int64_t high, int width) {
    const Word lowWord = constant(low);
    const Word highWord = constant(high);
    const Lit below = less(a, lowWord);
    const Lit above = less(highWord, a);
    return extended(choose(below, lowWord, choose(above, highWord, a)), width);
}

std::int64_t laneValue(const std::vector<std::uint64_t>& values, const Word& word, int lane) {
    std::uint64_t bits = 0;
    for (int i = 0; i < 64; ++i) {
        const Lit bit = i < word.width() ? word.bits[static_cast<std::size_t>(i)] : word.sign();
        bits |= ((AndGraph::value(values, bit) >> lane) & 1u) << i;
    }
    return static_cast<std::int64_t>(bits);
}

} // namespace rs::prove
