// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Network.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace rs::ladder {

lang::Expr toExpr(const Circuit& circuit);
// The statement of an output, without a condition.
lang::Statement toStatement(const Output& output);

// The statements of a rung, one per output, each with its own copy of the
// condition and the output's trailing comment.
std::vector<lang::Line> toLines(const Rung& rung);

// The lines of a step. A network keeps the record it was read with (with its
// comment brought up to date). A network without one gets a record when the
// text needs it to read back as the same network: when it has a comment, not
// exactly one statement, or starts with a comment line, or when a network
// before it in the step has a record. In a step where none had a record,
// once one network needs a record every network gets one
// (docs/file-format.md).
std::vector<lang::Line> toLines(const StepLadder& step);

// Lines [first, first + removed) of a step's text and what they become.
struct LineRun {
    std::size_t first = 0;
    std::size_t removed = 0;
    std::vector<lang::Line> lines;
};

// What replacing networks [first, first + removed) of `step` by `added`
// changes in the step's lines as toLines writes them, at the cost of those
// networks: `step` must be as read from its lines (toLadder), so that its
// networks give back the lines they were read from. Nothing when more of the
// step is written anew (a record the other networks gain or lose) or a block
// network is among the networks removed or added (its instance's statements
// and variables come from its block).
std::optional<LineRun> networkRunLines(const StepLadder& step, std::size_t first,
                                       std::size_t removed, const std::vector<Network>& added);

} // namespace rs::ladder
