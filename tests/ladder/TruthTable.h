// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ladder/Circuit.h"
#include "lang/Ast.h"

#include <set>
#include <string>
#include <vector>

namespace rs::test {

inline constexpr std::size_t kMostAtoms = 14;

// A small reference evaluator for the combinational part of a condition.
// Its inputs ("atoms") are the bits of contacts (by operand), each
// comparison (by its text), and for each edge and timer occurrence (by its
// place in pre-order) the edge seen or the timer's own state. A TON or TPS
// gives power only while its input has it, so its output is input AND its
// state; a TOF holds power after its input falls: input OR its state. A
// negated timer passes its input AND NOT its output.
struct TruthTable {
    std::set<std::string> atoms;
    // Power at the right end for every assignment of the atoms; none when
    // there are more than kMostAtoms of them.
    std::vector<bool> rows;

    friend bool operator==(const TruthTable&, const TruthTable&) = default;
};

// Power flowing through the expression: AND in series, OR in parallel.
TruthTable truthTable(const lang::Expr& expr);
// Power flowing through the circuit, evaluated on the ladder model itself.
TruthTable truthTable(const ladder::Circuit& circuit);
// The expression as Boolean algebra (for conditions without timers): the
// AND of a group's values, the OR of a group's values, the literals.
TruthTable algebraTable(const lang::Expr& expr);

} // namespace rs::test
