// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Editing.h"

#include <optional>

namespace rs::ladder {

// A place in a unit's ladder, as an editor selects it: a network as a whole,
// a node of one of its rungs' conditions (an element or a whole series or
// parallel group), or an output of a rung. Steps are numbered as unitLadder()
// lists them, networks within their step, both from 0.
struct Cursor {
    int step = -1;
    int network = -1;
    std::optional<ElementPath> node;   // a condition node
    std::optional<ElementPath> output; // path.item is the rung; with outputIndex
    int outputIndex = -1;

    bool valid() const { return step >= 0 && network >= 0; }
    bool wholeNetwork() const { return valid() && !node && !output; }
    bool sameNetwork(int s, int n) const { return step == s && network == n; }
    friend bool operator==(const Cursor&, const Cursor&) = default;
};

} // namespace rs::ladder
