// SPDX-License-Identifier: GPL-3.0-or-later
#include "prove/Word.h"

#include <gtest/gtest.h>

#include <random>

namespace {

using rs::prove::AndGraph;
using rs::prove::Word;
using rs::prove::WordBuilder;

// Numbers as circuits compute what 64-bit C++ computes: each operation over
// 64 random operand pairs at once, values near the limits included.
class WordTest : public ::testing::Test {
protected:
    std::int64_t pick(int width) {
        const std::int64_t low = -(std::int64_t{1} << (width - 1));
        const std::int64_t high = (std::int64_t{1} << (width - 1)) - 1;
        switch (std::uniform_int_distribution<int>(0, 4)(random)) {
        case 0:
            return low + std::uniform_int_distribution<int>(0, 2)(random);
        case 1:
            return high - std::uniform_int_distribution<int>(0, 2)(random);
        case 2:
            return std::uniform_int_distribution<int>(-3, 3)(random);
        default:
            return std::uniform_int_distribution<std::int64_t>(low, high)(random);
        }
    }

    // Runs `check` on 64 lanes of fresh operands of the given widths.
    template <typename Build, typename Expect>
    void compare(int widthA, int widthB, Build build, Expect expect, int rounds = 20) {
        for (int round = 0; round < rounds; ++round) {
            AndGraph graph;
            WordBuilder w(graph);
            const Word a = w.variables(widthA);
            const Word b = w.variables(widthB);
            const Word result = build(w, a, b);
            std::vector<std::uint64_t> values(graph.nodes(), 0);
            std::int64_t x[64];
            std::int64_t y[64];
            for (int lane = 0; lane < 64; ++lane) {
                x[lane] = pick(widthA);
                y[lane] = pick(widthB);
                for (int i = 0; i < widthA; ++i)
                    values[rs::prove::nodeOf(a.bits[i])] |= std::uint64_t((x[lane] >> i) & 1)
                                                            << lane;
                for (int i = 0; i < widthB; ++i)
                    values[rs::prove::nodeOf(b.bits[i])] |= std::uint64_t((y[lane] >> i) & 1)
                                                            << lane;
            }
            graph.evaluate(values);
            for (int lane = 0; lane < 64; ++lane) {
                const auto wanted = expect(x[lane], y[lane]);
                if (!wanted)
                    continue;
                ASSERT_EQ(rs::prove::laneValue(values, result, lane), *wanted)
                    << x[lane] << ", " << y[lane];
            }
        }
    }

    std::mt19937_64 random{20261203};
};

TEST_F(WordTest, AddsAndSubtractsExactly) {
    compare(
        32, 16, [](WordBuilder& w, const Word& a, const Word& b) { return w.add(a, b); },
        [](std::int64_t a, std::int64_t b) { return std::optional(a + b); });
    compare(
        32, 32, [](WordBuilder& w, const Word& a, const Word& b) { return w.subtract(a, b); },
        [](std::int64_t a, std::int64_t b) { return std::optional(a - b); });
}

TEST_F(WordTest, MultipliesExactly) {
    compare(
        16, 16, [](WordBuilder& w, const Word& a, const Word& b) { return w.multiply(a, b); },
        [](std::int64_t a, std::int64_t b) { return std::optional(a * b); });
    compare(
        32, 32, [](WordBuilder& w, const Word& a, const Word& b) { return w.multiply(a, b); },
        [](std::int64_t a, std::int64_t b) { return std::optional(a * b); }, 5);
}

TEST_F(WordTest, DividesAsCxxDoes) {
    for (int width : {16, 33}) {
        compare(
            width, width,
            [](WordBuilder& w, const Word& a, const Word& b) {
                Word q, r;
                w.divide(a, b, q, r);
                return q;
            },
            [](std::int64_t a, std::int64_t b) {
                return b == 0 ? std::nullopt : std::optional(a / b);
            });
        compare(
            width, width,
            [](WordBuilder& w, const Word& a, const Word& b) {
                Word q, r;
                w.divide(a, b, q, r);
                return r;
            },
            [](std::int64_t a, std::int64_t b) {
                return b == 0 ? std::nullopt : std::optional(a % b);
            });
    }
}

TEST_F(WordTest, ComparesAndSaturates) {
    compare(
        17, 32, [](WordBuilder& w, const Word& a, const Word& b) { return w.bit(w.less(a, b)); },
        [](std::int64_t a, std::int64_t b) { return std::optional<std::int64_t>(a < b); });
    compare(
        16, 16, [](WordBuilder& w, const Word& a, const Word& b) { return w.bit(w.equal(a, b)); },
        [](std::int64_t a, std::int64_t b) { return std::optional<std::int64_t>(a == b); });
    compare(
        33, 1,
        [](WordBuilder& w, const Word& a, const Word&) {
            return w.saturated(a, -32768, 32767, 16);
        },
        [](std::int64_t a, std::int64_t) {
            return std::optional(std::clamp<std::int64_t>(a, -32768, 32767));
        });
}

TEST(AndGraphTest, FoldsConstantsAndSharesEqualGates) {
    AndGraph graph;
    const auto a = graph.variable();
    const auto b = graph.variable();
    EXPECT_EQ(graph.conj(a, rs::prove::kFalse), rs::prove::kFalse);
    EXPECT_EQ(graph.conj(a, rs::prove::kTrue), a);
    EXPECT_EQ(graph.conj(a, rs::prove::negate(a)), rs::prove::kFalse);
    EXPECT_EQ(graph.conj(a, b), graph.conj(b, a));
    const auto before = graph.nodes();
    graph.conj(a, b);
    EXPECT_EQ(graph.nodes(), before);
}

} // namespace
