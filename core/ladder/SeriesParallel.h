// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/SourceLocation.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace rs::ladder {

// A rung's condition as a series/parallel circuit of some target's elements:
// an element, elements and circuits in series (left to right), or circuits in
// parallel (top to bottom). Every target draws its rungs with this shape;
// what an element is, is the target's (Pluto: Element.h, PL110: pl110/Program.h).
//
// Canonical form, which every function here keeps: a series or parallel
// circuit has at least two parts, and none of its parts is of its own kind
// (a series inside a series is one longer series).
template <class ElementType> struct SeriesParallel {
    enum class Kind : std::uint8_t { Element, Series, Parallel };

    Kind kind = Kind::Element;
    ElementType element;               // Kind::Element
    std::vector<SeriesParallel> parts; // Series, Parallel
    lang::SourceLocation location;     // of the element in the text, for diagnostics

    static SeriesParallel of(ElementType element) {
        SeriesParallel circuit;
        circuit.element = std::move(element);
        return circuit;
    }
    // Parts in series or in parallel, merged into canonical form; one part
    // alone is that part.
    static SeriesParallel series(std::vector<SeriesParallel> parts) {
        return group(Kind::Series, std::move(parts));
    }
    static SeriesParallel parallel(std::vector<SeriesParallel> parts) {
        return group(Kind::Parallel, std::move(parts));
    }

    bool isElement() const { return kind == Kind::Element; }

    friend bool operator==(const SeriesParallel&, const SeriesParallel&) = default;

private:
    static SeriesParallel group(Kind kind, std::vector<SeriesParallel> parts) {
        SeriesParallel circuit;
        circuit.kind = kind;
        circuit.parts = std::move(parts);
        normalize(circuit);
        return circuit;
    }
};

// Brings a circuit whose groups may be nested in their own kind or hold fewer
// than two parts into canonical form. A group without parts stays empty.
template <class ElementType> void normalize(SeriesParallel<ElementType>& circuit) {
    if (circuit.isElement())
        return;
    std::vector<SeriesParallel<ElementType>> merged;
    for (auto& part : circuit.parts) {
        normalize(part);
        if (!part.isElement() && part.parts.empty())
            continue;
        if (part.kind == circuit.kind) {
            for (auto& inner : part.parts)
                merged.push_back(std::move(inner));
        } else {
            merged.push_back(std::move(part));
        }
    }
    circuit.parts = std::move(merged);
    if (circuit.parts.size() == 1) {
        SeriesParallel<ElementType> only = std::move(circuit.parts.front());
        circuit = std::move(only);
    }
}

// Number of nodes in the circuit, groups included: the element numbers a
// statement's condition uses are 1 .. nodeCount (pre-order, as the compiler
// numbers them).
template <class ElementType> int nodeCount(const SeriesParallel<ElementType>& circuit) {
    int count = 1;
    for (const auto& part : circuit.parts)
        count += nodeCount(part);
    return count;
}

} // namespace rs::ladder
