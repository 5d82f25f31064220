// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Element.h"

#include <cstdint>
#include <vector>

namespace rs::ladder {

// A rung's condition as a series/parallel circuit: an element, elements and
// circuits in series (left to right), or circuits in parallel (top to
// bottom). The language's expression tree has the same shape: series is AND,
// parallel is OR.
//
// Canonical form, which every function here keeps: a series or parallel
// circuit has at least two parts, and none of its parts is of its own kind
// (a series inside a series is one longer series).
struct Circuit {
    enum class Kind : std::uint8_t { Element, Series, Parallel };

    Kind kind = Kind::Element;
    Element element;               // Kind::Element
    std::vector<Circuit> parts;    // Series, Parallel
    lang::SourceLocation location; // of the element in the text, for diagnostics

    static Circuit of(Element element);
    // Parts in series or in parallel, merged into canonical form; one part
    // alone is that part.
    static Circuit series(std::vector<Circuit> parts);
    static Circuit parallel(std::vector<Circuit> parts);

    bool isElement() const { return kind == Kind::Element; }

    friend bool operator==(const Circuit&, const Circuit&) = default;
};

// Brings a circuit whose groups may be nested in their own kind or hold fewer
// than two parts into canonical form. A group without parts stays empty.
void normalize(Circuit& circuit);

// Number of nodes in the circuit, groups included: the element numbers a
// statement's condition uses are 1 .. nodeCount (pre-order, as the compiler
// numbers them).
int nodeCount(const Circuit& circuit);

} // namespace rs::ladder
