// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Circuit.h"
#include "Output.h"

#include <optional>
#include <vector>

namespace rs::ladder {

// One rung: a condition circuit from the left rail, ending in one or more
// outputs in parallel. The language writes each output as its own statement
// with a copy of the condition.
struct Rung {
    std::optional<Circuit> condition; // none: the outputs are on whenever the rung runs
    std::vector<Output> outputs;      // at least one

    friend bool operator==(const Rung&, const Rung&) = default;
};

// Whether the rung means what its statements mean. Several outputs can share
// one condition only when evaluating the condition again for each of them
// gives the same power: the condition holds no edge or timer (each occurrence
// in the text has its own memory) and reads nothing an earlier output writes.
bool isExpressible(const Rung& rung);

// Whether `next`, standing right after `rung`, is the same circuit with more
// outputs: then the text cannot tell the two apart, and the ladder shows them
// as one rung.
bool canJoin(const Rung& rung, const Rung& next);

} // namespace rs::ladder
