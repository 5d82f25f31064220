// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "AndGraph.h"

#include <cstdint>
#include <vector>

// Signed two's-complement numbers as literals, least significant bit first.
// Every operation is exact: its result is as wide as it must be, so a sum or
// product never wraps and saturation is decided on the true value, as the
// engine does in 64 bits (core/sim/engine/InstructionMeaning.h).
namespace rs::prove {

struct Word {
    std::vector<Lit> bits;

    int width() const { return static_cast<int>(bits.size()); }
    Lit sign() const { return bits.empty() ? kFalse : bits.back(); }
};

class WordBuilder {
public:
    explicit WordBuilder(AndGraph& graph) : m_graph(graph) {}

    AndGraph& graph() { return m_graph; }

    Word constant(std::int64_t value, int width = 0) const; // width 0: as narrow as it fits
    Word variables(int width);
    Word extended(const Word& a, int width) const;      // sign extension (or truncation)
    Word bit(Lit a) const { return Word{{a, kFalse}}; } // 0 or 1

    Word add(const Word& a, const Word& b);
    Word subtract(const Word& a, const Word& b);
    Word negated(const Word& a);
    Word multiply(const Word& a, const Word& b);
    // Truncating towards zero, as C++ does; the remainder takes the dividend's
    // sign. The divisor must not be 0 (the caller chooses what 0 gives).
    void divide(const Word& dividend, const Word& divisor, Word& quotient, Word& remainder);

    Lit equal(const Word& a, const Word& b);
    Lit less(const Word& a, const Word& b); // signed
    Lit isZero(const Word& a);
    Word choose(Lit c, const Word& a, const Word& b);
    // The value clamped to [low, high], `width` bits wide.
    Word saturated(const Word& a, std::int64_t low, std::int64_t high, int width);
    // The smallest width whose range holds every value `a` can take, when
    // its top bits are copies of the sign (constants folded).
    static Word trimmed(Word a);

private:
    Word unsignedAdd(const Word& a, const Word& b, Lit carry, int width);

    AndGraph& m_graph;
};

// The value of a word under one evaluation lane of AndGraph::evaluate.
std::int64_t laneValue(const std::vector<std::uint64_t>& values, const Word& word, int lane);

} // namespace rs::prove
