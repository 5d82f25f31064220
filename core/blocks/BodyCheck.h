// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "BlockLibrary.h"
#include "BodyTemplate.h"

#include <string>
#include <vector>

namespace rs::blocks {

// A problem in a block's body: the body line (0-based) and the 1-based
// character column in that line as the library file holds it.
struct BodyProblem {
    std::size_t bodyLine = 0;
    int column = 1;
    std::string message;
};

struct BodyCheckResult {
    std::vector<BodyProblem> problems;
    int timers = 0; // TON, TPS and TOF occurrences in the body
    std::vector<bool> pinUsed;
    std::vector<bool> privateUsed;
};

// Holds the body to what the format promises: every placeholder names a pin
// or private variable of the block, and with sample operands put in (pins
// and private variables each their own address of their kind) the lines
// read as Pluto statements with the project's parser: no declarations, step
// headers, jumps or sequence resets, which belong to the program around an
// instance.
BodyCheckResult checkBody(const BlockDefinition& block);

// The operand a placeholder stands for when the body is checked.
std::string sampleOperand(const BlockDefinition& block, const Placeholder& placeholder);

} // namespace rs::blocks
