// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ElementKind.h"
#include "lang/Ast.h"

#include <cstdint>
#include <variant>

// The elements a rung's condition is drawn with. Each one is exactly one leaf
// of the language's expression tree, so the two convert without loss.
namespace rs::ladder {

// An edge contact: P(x), N(x), /P(x), /N(x).
bool isEdge(ElementKind kind);

// A contact on a bit: an input, output, memory or register bit.
struct Contact {
    ElementKind kind = ElementKind::NormallyOpen; // a contact's or an edge's
    lang::Operand operand;
    bool operandNegated = false; // edges only: P(/x) sees the edges of the inverted bit
    friend bool operator==(const Contact&, const Contact&) = default;
};

// A timer box in series: the power at its left is its input, its output
// powers what stands to its right (negated: input and not output).
struct TimerBox {
    lang::TimerSpelling spelling = lang::TimerSpelling::TON;
    lang::TimerPreset preset;
    bool negated = false;
    friend bool operator==(const TimerBox&, const TimerBox&) = default;
};

// A comparison box: passes power when "left op right" holds (negated: when not).
struct ComparisonBox {
    lang::Operand left;
    lang::CompareOp op = lang::CompareOp::Equal;
    lang::Value right;
    bool negated = false;
    friend bool operator==(const ComparisonBox&, const ComparisonBox&) = default;
};

using Element = std::variant<Contact, TimerBox, ComparisonBox>;

} // namespace rs::ladder
