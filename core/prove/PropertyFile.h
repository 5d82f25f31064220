// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Address.h"
#include "lang/Ast.h"
#include "lang/Diagnostic.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rs::sim {
class OperandNames;
}

// Property files (.prop): what a program must always do, as
// ../shared/spec/properties.md defines them.
namespace rs::prove {

// A condition on the variables at the end of a scan, in the language's syntax.
struct Condition {
    enum class Kind : std::uint8_t { Bit, Not, And, Or, Compare } kind = Kind::Bit;
    lang::Address operand; // Bit; Compare's left side (kind Sequence: the active step)
    lang::CompareOp op = lang::CompareOp::Equal;
    bool rightIsConstant = true;
    lang::Address right;
    std::int64_t constant = 0;
    std::vector<Condition> children;
    int column = 0;
};

struct Property {
    enum class Kind : std::uint8_t {
        Always,  // always A
        Never,   // never A
        Implies, // always A -> B
        Within,  // always A -> within DURATION B
        Next,    // always A -> next B
        Assume,  // assume A
        Cover,   // cover A
    } kind = Kind::Always;
    Condition first;
    Condition second;
    std::int64_t durationMs = 0; // Within, as written
    int line = 0;
    std::string text; // the line as written, without its comment
};

struct PropertyFile {
    std::vector<Property> properties; // in file order, assumptions included
    int cycleMs = 10;
    lang::Diagnostics diagnostics; // syntax errors: nothing is proved
};

// Lines end at LF, CRLF or a lone CR; a leading byte-order mark is skipped.
// Operands resolve as a scenario's do (symbolic names, addresses of any unit
// of the project). Refuses a file with no property to prove or cover.
PropertyFile parseProperties(std::string_view text, const sim::OperandNames& names);

// The scans of a `within` window: the duration in cycles, rounded down.
inline std::int64_t windowScans(const Property& property, int cycleMs) {
    return property.durationMs / cycleMs;
}

// Every variable a condition reads.
void collectOperands(const Condition& condition, std::vector<lang::Address>& into);

} // namespace rs::prove
