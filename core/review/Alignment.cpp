// SPDX-License-Identifier: GPL-3.0-or-later
#include "Alignment.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace rs::review {

namespace {

// The table of a longest common subsequence needs (n+1)(m+1) cells; above
// this (some 64 MB) the middle of two long sequences is paired by position.
constexpr std::size_t kMaxTableCells = 16'000'000;

// Pairs the unmatched old items [oldFirst, oldEnd) with the unmatched new
// items [newFirst, newEnd) in order.
void pairGap(std::vector<Pairing>& out, int oldFirst, int oldEnd, int newFirst, int newEnd) {
    while (oldFirst < oldEnd && newFirst < newEnd)
        out.push_back({Pairing::Changed, oldFirst++, newFirst++});
    while (oldFirst < oldEnd)
        out.push_back({Pairing::Removed, oldFirst++, -1});
    while (newFirst < newEnd)
        out.push_back({Pairing::Added, -1, newFirst++});
}

// Same pairs of a longest common subsequence of before[from..] and after[from..]
// up to the given ends, in order.
std::vector<std::pair<int, int>> commonSubsequence(const std::vector<std::string>& before,
                                                   const std::vector<std::string>& after,
                                                   int oldFrom, int oldEnd, int newFrom,
                                                   int newEnd) {
    const std::size_t n = static_cast<std::size_t>(oldEnd - oldFrom);
    const std::size_t m = static_cast<std::size_t>(newEnd - newFrom);
    // length[i][j]: of the common subsequence of the items from i and from j on.
    std::vector<std::uint32_t> length((n + 1) * (m + 1), 0);
    const auto at = [&](std::size_t i, std::size_t j) -> std::uint32_t& {
        return length[i * (m + 1) + j];
    };
    for (std::size_t i = n; i-- > 0;)
        for (std::size_t j = m; j-- > 0;)
            at(i, j) = before[oldFrom + i] == after[newFrom + j]
                           ? at(i + 1, j + 1) + 1
                           : std::max(at(i + 1, j), at(i, j + 1));
    std::vector<std::pair<int, int>> pairs;
    std::size_t i = 0, j = 0;
    while (i < n && j < m) {
        if (before[oldFrom + i] == after[newFrom + j]) {
            pairs.emplace_back(oldFrom + static_cast<int>(i), newFrom + static_cast<int>(j));
            ++i;
            ++j;
        } else if (at(i + 1, j) >= at(i, j + 1)) {
            ++i;
        } else {
            ++j;
        }
    }
    return pairs;
}

} // namespace

std::vector<Pairing> align(const std::vector<std::string>& before,
                           const std::vector<std::string>& after) {
    const int n = static_cast<int>(before.size());
    const int m = static_cast<int>(after.size());
    std::vector<Pairing> out;
    int start = 0;
    while (start < n && start < m && before[start] == after[start]) {
        out.push_back({Pairing::Same, start, start});
        ++start;
    }
    int oldEnd = n, newEnd = m;
    while (oldEnd > start && newEnd > start && before[oldEnd - 1] == after[newEnd - 1]) {
        --oldEnd;
        --newEnd;
    }
    const std::size_t cells =
        static_cast<std::size_t>(oldEnd - start + 1) * static_cast<std::size_t>(newEnd - start + 1);
    int oldAt = start, newAt = start;
    if (cells <= kMaxTableCells)
        for (const auto& [i, j] : commonSubsequence(before, after, start, oldEnd, start, newEnd)) {
            pairGap(out, oldAt, i, newAt, j);
            out.push_back({Pairing::Same, i, j});
            oldAt = i + 1;
            newAt = j + 1;
        }
    pairGap(out, oldAt, oldEnd, newAt, newEnd);
    for (int k = 0; k < n - oldEnd; ++k)
        out.push_back({Pairing::Same, oldEnd + k, newEnd + k});
    return out;
}

} // namespace rs::review
