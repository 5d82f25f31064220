// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "SeriesParallel.h"

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <optional>
#include <string>
#include <utility>
#include <vector>

// Editing a rung's condition, for every target's elements: insert in series
// or in a parallel branch, take a node out. These change the circuit in
// place without normalizing, so that the paths of other nodes stay valid
// while an edit is under way; the caller normalizes (normalizeCondition) and
// decides whether the result is acceptable. Each returns why it refused, or
// an empty string.
namespace rs::ladder {

enum class Side : std::uint8_t { Before, After };

inline constexpr const char* kNoCircuitNode = "there is no element there";

// A node's place: the part indices down from the condition's root (empty:
// the root); nothing when there is no such node.
template <class E>
SeriesParallel<E>* nodeAt(std::optional<SeriesParallel<E>>& condition,
                          const std::vector<std::size_t>& path) {
    if (!condition)
        return nullptr;
    SeriesParallel<E>* node = &*condition;
    for (std::size_t index : path) {
        if (index >= node->parts.size())
            return nullptr;
        node = &node->parts[index];
    }
    return node;
}

template <class E>
const SeriesParallel<E>* nodeAt(const std::optional<SeriesParallel<E>>& condition,
                                const std::vector<std::size_t>& path) {
    return nodeAt(const_cast<std::optional<SeriesParallel<E>>&>(condition), path);
}

// What stands where a node was taken out: an empty group, which normalizing
// drops.
template <class E> SeriesParallel<E> emptyGroup() {
    SeriesParallel<E> empty;
    empty.kind = SeriesParallel<E>::Kind::Series;
    return empty;
}

// Canonical form; a condition left without elements is none.
template <class E> void normalizeCondition(std::optional<SeriesParallel<E>>& condition) {
    if (!condition)
        return;
    normalize(*condition);
    if (!condition->isElement() && condition->parts.empty())
        condition.reset();
}

// Puts a part in series before or after the node; on a rung without a
// condition the root path makes the part its condition.
template <class E>
std::string insertInSeries(std::optional<SeriesParallel<E>>& condition,
                           const std::vector<std::size_t>& path, SeriesParallel<E> part,
                           Side side) {
    if (!condition) {
        if (!path.empty())
            return kNoCircuitNode;
        condition = std::move(part);
        return {};
    }
    SeriesParallel<E>* node = nodeAt(condition, path);
    if (!node)
        return kNoCircuitNode;
    if (!path.empty()) {
        SeriesParallel<E>* parent = nodeAt(condition, {path.begin(), path.end() - 1});
        if (parent->kind == SeriesParallel<E>::Kind::Series) {
            auto at = parent->parts.begin() + static_cast<std::ptrdiff_t>(path.back()) +
                      (side == Side::After ? 1 : 0);
            parent->parts.insert(at, std::move(part));
            return {};
        }
    }
    SeriesParallel<E> series;
    series.kind = SeriesParallel<E>::Kind::Series;
    if (side == Side::Before)
        series.parts = {std::move(part), std::move(*node)};
    else
        series.parts = {std::move(*node), std::move(part)};
    *node = std::move(series);
    return {};
}

// Puts a branch in parallel around the node, or around `seriesParts`
// consecutive parts of a series starting at the node.
template <class E>
std::string insertInParallel(std::optional<SeriesParallel<E>>& condition,
                             const std::vector<std::size_t>& path, SeriesParallel<E> branch,
                             std::size_t seriesParts = 1) {
    SeriesParallel<E>* node = nodeAt(condition, path);
    if (!node)
        return condition ? kNoCircuitNode : "a parallel branch needs an element to go around";
    if (seriesParts == 1) {
        *node = SeriesParallel<E>::parallel({std::move(*node), std::move(branch)});
        return {};
    }
    const char* const notASeries =
        "only parts of a series can be taken into a parallel branch together";
    if (path.empty())
        return notASeries;
    SeriesParallel<E>* parent = nodeAt(condition, {path.begin(), path.end() - 1});
    const std::size_t first = path.back();
    if (parent->kind != SeriesParallel<E>::Kind::Series || seriesParts == 0 ||
        first + seriesParts > parent->parts.size())
        return notASeries;
    auto begin = parent->parts.begin() + static_cast<std::ptrdiff_t>(first);
    auto end = begin + static_cast<std::ptrdiff_t>(seriesParts);
    SeriesParallel<E> taken =
        SeriesParallel<E>::series({std::make_move_iterator(begin), std::make_move_iterator(end)});
    *begin = SeriesParallel<E>::parallel({std::move(taken), std::move(branch)});
    parent->parts.erase(begin + 1, end);
    return {};
}

// Takes the node (an element or a whole group) out, leaving an empty group.
template <class E>
std::string removeNode(std::optional<SeriesParallel<E>>& condition,
                       const std::vector<std::size_t>& path) {
    SeriesParallel<E>* node = nodeAt(condition, path);
    if (!node)
        return kNoCircuitNode;
    *node = emptyGroup<E>();
    return {};
}

} // namespace rs::ladder
