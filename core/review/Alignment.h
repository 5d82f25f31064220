// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <vector>

// Lines up two sequences of networks, each given by what it means, so that an
// inserted network reads as one added network and not as every later one
// changed.
namespace rs::review {

struct Pairing {
    enum Kind { Same, Changed, Added, Removed } kind = Same;
    int oldIndex = -1; // -1 for Added
    int newIndex = -1; // -1 for Removed
    friend bool operator==(const Pairing&, const Pairing&) = default;
};

// Every old item appears once (Same, Changed or Removed) and every new item
// once (Same, Changed or Added), each side in its order. Same pairs are a
// longest common subsequence of equal items; between two of them, the
// unmatched items are paired in order as Changed, and what is left over on
// one side is Added or Removed. Sequences too long for that after their
// common start and end are paired by position.
std::vector<Pairing> align(const std::vector<std::string>& before,
                           const std::vector<std::string>& after);

} // namespace rs::review
