// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Network.h"

#include <functional>

// The language's syntax tree in ladder form. Together with LadderToText.h
// this is a pair of inverse functions: converting a step to ladder and back
// gives the same lines, so the canonical text is the same.
namespace rs::ladder {

// A parsed condition (OR and AND flattened, no negated group) as a circuit.
Circuit toCircuit(const lang::Expr& expr);

Output toOutput(const lang::Statement& statement, const std::optional<std::string>& comment);

Rung toRung(const lang::Statement& statement, const std::optional<std::string>& comment);

// The networks of a step, grouped as project::networksOf groups them. In a
// network that a ";@network" record groups, statements that follow each other
// with the same condition and can share it (see canJoin) are one rung with
// several outputs. A malformed record is a comment like any other.
//
// A block instance (a well-formed ";@block" … ";@end" pair) is one network
// when `shown` says so, or always when no `shown` is given; otherwise its
// records are comments among ordinary networks, as an expansion edited by
// hand is shown (blocks.md).
using BlockShown = std::function<bool(const blocks::BlockInstance&)>;
StepLadder toLadder(const lang::Step& step, const BlockShown& shown = {});

} // namespace rs::ladder
