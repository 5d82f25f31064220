// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "CircuitEditing.h"
#include "Network.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

// Editing operations on the ladder model. Each one either leaves a network the
// language can express, in the canonical form reading its text gives back
// (circuits normalized, adjacent rungs that can share a condition joined), or
// refuses and changes nothing. So converting an edited network to text never
// fails and reading that text gives the same network.
namespace rs::ladder {

// A node of a rung's condition: the rung's index among the network's items,
// and the part indices down from the condition's root (empty: the root).
struct ElementPath {
    std::size_t item = 0;
    std::vector<std::size_t> node;
    friend bool operator==(const ElementPath&, const ElementPath&) = default;
};

struct EditResult {
    std::string refusal; // why nothing was changed; empty when the edit was made
    bool done() const { return refusal.empty(); }
};

// Puts an element in series before or after the node. On a rung without a
// condition the root path makes the element its condition.
EditResult insertInSeries(Network& network, const ElementPath& at, Element element, Side side);

// Puts an element in a new parallel branch around the node, or around
// `seriesParts` consecutive parts of a series starting at the node.
EditResult insertInParallel(Network& network, const ElementPath& at, Element element,
                            std::size_t seriesParts = 1);

// Removes the node (an element or a whole group); a rung whose condition
// becomes empty has its outputs on whenever it runs.
EditResult removeNode(Network& network, const ElementPath& at);

// Changes an element's kind or operand.
EditResult replaceElement(Network& network, const ElementPath& at, Element element);

// Moves a node next to another, in series before or after it, within a
// network or from one network to another (`from` and `to` may be the same).
EditResult moveNode(Network& from, const ElementPath& node, Network& to, const ElementPath& target,
                    Side side);

// Puts a copy of a node next to another, in series before or after it, in
// the same network (next to itself too) or another; `from` stays as it is.
EditResult copyNode(const Network& from, const ElementPath& node, Network& to,
                    const ElementPath& target, Side side);

EditResult insertRung(Network& network, std::size_t item, Rung rung);
EditResult removeItem(Network& network, std::size_t item);

// Adds an output in parallel to the rung's outputs, after the others.
EditResult addOutput(Network& network, std::size_t item, Output output);
EditResult replaceOutput(Network& network, std::size_t item, std::size_t index, Output output);
// Removing a rung's only output removes the rung.
EditResult removeOutput(Network& network, std::size_t item, std::size_t index);

} // namespace rs::ladder
