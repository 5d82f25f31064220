#pragma once

#ifndef Q_MOC_RUN
#include "ladder/Editing.h"
#endif

#include <optional>

namespace rs::ui {

// What is selected on a ladder page: a network as a whole, a node of one of
// its rungs' conditions (an element or a whole series or parallel group), or
// an output of a rung.
struct LadderCursor {
    int step = -1; // index among the page's steps
    int network = -1;
    std::optional<ladder::ElementPath> node;   // a condition node
    std::optional<ladder::ElementPath> output; // path.item is the rung; with outputIndex
    int outputIndex = -1;

    bool valid() const { return step >= 0 && network >= 0; }
    bool wholeNetwork() const { return valid() && !node && !output; }
    bool sameNetwork(int s, int n) const { return step == s && network == n; }
    friend bool operator==(const LadderCursor&, const LadderCursor&) = default;
};

} // namespace rs::ui
