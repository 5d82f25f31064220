// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Ast.h"

#include <optional>
#include <string>

namespace rs::ladder {

// What stands at the right end of a rung: a coil, set, reset or toggle coil
// on a bit, a jump, a sequence reset or an arithmetic box. It is one statement
// of the language without its condition.
struct Output {
    lang::StatementKind kind = lang::StatementKind::Coil;
    lang::Operand target; // Coil, Set, Reset, Toggle; the sequence of a SequenceReset
    bool relativeJump = false;
    int jumpStep = 0;                   // Jump: absolute step, or signed offset when relative
    lang::Assignment assignment;        // Assign
    std::optional<std::string> comment; // the trailing comment of the statement's line
    lang::SourceLocation location;      // the statement's, for diagnostics on the drawing

    friend bool operator==(const Output&, const Output&) = default;
};

} // namespace rs::ladder
