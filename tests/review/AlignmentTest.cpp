// SPDX-License-Identifier: GPL-3.0-or-later
#include "review/Alignment.h"

#include <gtest/gtest.h>

#include <random>

using rs::review::align;
using rs::review::Pairing;

namespace {

using Items = std::vector<std::string>;

Items randomItems(std::mt19937& random, int maxLength) {
    // Few distinct items, so that repeats and ambiguous matches are common.
    Items items(std::uniform_int_distribution<int>(0, maxLength)(random));
    for (auto& item : items)
        item = std::string(
            1, static_cast<char>('a' + std::uniform_int_distribution<int>(0, 4)(random)));
    return items;
}

// The longest common subsequence's length, by the textbook recurrence.
std::size_t lcsLength(const Items& a, const Items& b) {
    std::vector<std::vector<std::size_t>> t(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j)
            t[i][j] =
                a[i - 1] == b[j - 1] ? t[i - 1][j - 1] + 1 : std::max(t[i - 1][j], t[i][j - 1]);
    return t[a.size()][b.size()];
}

// Checks what align promises and rebuilds both sides from the pairing.
void expectConsistent(const Items& before, const Items& after) {
    const std::vector<Pairing> pairs = align(before, after);
    Items rebuiltOld, rebuiltNew;
    std::size_t same = 0;
    int nextOld = 0, nextNew = 0;
    for (const Pairing& p : pairs) {
        if (p.kind != Pairing::Added) {
            ASSERT_EQ(p.oldIndex, nextOld++);
            rebuiltOld.push_back(before[p.oldIndex]);
        } else {
            EXPECT_EQ(p.oldIndex, -1);
        }
        if (p.kind != Pairing::Removed) {
            ASSERT_EQ(p.newIndex, nextNew++);
            rebuiltNew.push_back(after[p.newIndex]);
        } else {
            EXPECT_EQ(p.newIndex, -1);
        }
        if (p.kind == Pairing::Same) {
            EXPECT_EQ(before[p.oldIndex], after[p.newIndex]);
            ++same;
        }
        if (p.kind == Pairing::Changed) {
            EXPECT_NE(before[p.oldIndex], after[p.newIndex]);
        }
    }
    EXPECT_EQ(rebuiltOld, before);
    EXPECT_EQ(rebuiltNew, after);
    EXPECT_EQ(same, lcsLength(before, after));
}

} // namespace

TEST(Alignment, ASequenceWithItselfIsAllSame) {
    std::mt19937 random(1);
    for (int round = 0; round < 200; ++round) {
        const Items items = randomItems(random, 40);
        for (const Pairing& p : align(items, items))
            EXPECT_EQ(p.kind, Pairing::Same);
    }
}

TEST(Alignment, RandomPairsCoverEachSideOnceInOrderWithALongestCommonPart) {
    std::mt19937 random(2);
    for (int round = 0; round < 2000; ++round) {
        const Items before = randomItems(random, 20);
        const Items after = randomItems(random, 20);
        SCOPED_TRACE(round);
        expectConsistent(before, after);
    }
}

TEST(Alignment, AnInsertedItemIsOneAddedNotEveryLaterOneChanged) {
    const auto pairs = align({"a", "b", "c", "d"}, {"a", "x", "b", "c", "d"});
    ASSERT_EQ(pairs.size(), 5u);
    EXPECT_EQ(pairs[1], (Pairing{Pairing::Added, -1, 1}));
    for (std::size_t i : {0u, 2u, 3u, 4u})
        EXPECT_EQ(pairs[i].kind, Pairing::Same);
}

TEST(Alignment, AReplacedItemIsOneChanged) {
    const auto pairs = align({"a", "b", "c"}, {"a", "x", "c"});
    ASSERT_EQ(pairs.size(), 3u);
    EXPECT_EQ(pairs[1], (Pairing{Pairing::Changed, 1, 1}));
}

TEST(Alignment, LongSequencesWithAChangeInTheMiddleStayCheap) {
    // Beyond the table's size the middle is paired by position; the common
    // start and end still match.
    Items before, after;
    for (int i = 0; i < 20000; ++i)
        before.push_back("n" + std::to_string(i));
    after = before;
    after[10000] = "changed";
    const auto pairs = align(before, after);
    ASSERT_EQ(pairs.size(), before.size());
    EXPECT_EQ(pairs[10000], (Pairing{Pairing::Changed, 10000, 10000}));
    // Reversed, nothing is common at either end: paired by position, every
    // item once.
    const Items reversed(before.rbegin(), before.rend());
    const auto mixed = align(before, reversed);
    ASSERT_EQ(mixed.size(), before.size());
    for (std::size_t i = 0; i < mixed.size(); ++i)
        EXPECT_EQ(mixed[i], (Pairing{Pairing::Changed, static_cast<int>(i), static_cast<int>(i)}));
}
