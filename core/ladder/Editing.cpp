// SPDX-License-Identifier: GPL-3.0-or-later
#include "Editing.h"

#include <algorithm>
#include <utility>

namespace rs::ladder {

namespace {

const char* const kNoRung = "there is no rung there";
const char* const kNoNode = "there is no element there";
const char* const kShared =
    "a rung with several outputs cannot hold an edge or a timer, nor read what one of its "
    "outputs writes: the text repeats the condition for every output";

// An empty group stands where a node was taken out; normalizing drops it, so
// the paths of other nodes stay valid until then.
Circuit placeholder() {
    Circuit empty;
    empty.kind = Circuit::Kind::Series;
    return empty;
}

Rung* rungAt(Network& network, std::size_t item) {
    if (item >= network.items.size())
        return nullptr;
    return std::get_if<Rung>(&network.items[item]);
}

Circuit* nodeAt(Rung& rung, const std::vector<std::size_t>& path) {
    if (!rung.condition)
        return nullptr;
    Circuit* node = &*rung.condition;
    for (std::size_t index : path) {
        if (index >= node->parts.size())
            return nullptr;
        node = &node->parts[index];
    }
    return node;
}

Element canonical(Element element) {
    if (auto* contact = std::get_if<Contact>(&element); contact && !isEdge(contact->kind))
        contact->operandNegated = false;
    return element;
}

void normalizeCondition(Rung& rung) {
    if (!rung.condition)
        return;
    normalize(*rung.condition);
    if (!rung.condition->isElement() && rung.condition->parts.empty())
        rung.condition.reset();
}

// Normalizes every condition and joins adjacent rungs the text cannot tell
// apart; refuses a rung the text cannot say.
EditResult settle(Network& network) {
    std::vector<NetworkItem> items;
    for (auto& item : network.items) {
        if (auto* rung = std::get_if<Rung>(&item)) {
            if (network.block)
                return {"a block network holds its block alone: add a network for the rung"};
            normalizeCondition(*rung);
            if (!isExpressible(*rung))
                return {kShared};
            if (!items.empty())
                if (auto* previous = std::get_if<Rung>(&items.back());
                    previous && canJoin(*previous, *rung)) {
                    for (auto& output : rung->outputs)
                        previous->outputs.push_back(std::move(output));
                    continue;
                }
        }
        items.push_back(std::move(item));
    }
    network.items = std::move(items);
    return {};
}

// Runs an edit on a copy and keeps the copy only when the edit and the
// result are acceptable.
template <typename Edit> EditResult edit(Network& network, Edit&& change) {
    Network copy = network;
    if (EditResult result = change(copy); !result.done())
        return result;
    if (EditResult result = settle(copy); !result.done())
        return result;
    network = std::move(copy);
    return {};
}

// Inserts without normalizing, so that placeholders elsewhere keep their place.
EditResult insertRaw(Rung& rung, const std::vector<std::size_t>& path, Circuit part, Side side) {
    if (!rung.condition) {
        if (!path.empty())
            return {kNoNode};
        rung.condition = std::move(part);
        return {};
    }
    Circuit* node = nodeAt(rung, path);
    if (!node)
        return {kNoNode};
    if (!path.empty()) {
        std::vector<std::size_t> parentPath(path.begin(), path.end() - 1);
        Circuit* parent = nodeAt(rung, parentPath);
        if (parent->kind == Circuit::Kind::Series) {
            auto at = parent->parts.begin() + static_cast<std::ptrdiff_t>(path.back()) +
                      (side == Side::After ? 1 : 0);
            parent->parts.insert(at, std::move(part));
            return {};
        }
    }
    Circuit series;
    series.kind = Circuit::Kind::Series;
    if (side == Side::Before)
        series.parts = {std::move(part), std::move(*node)};
    else
        series.parts = {std::move(*node), std::move(part)};
    *node = std::move(series);
    return {};
}

} // namespace

EditResult insertInSeries(Network& network, const ElementPath& at, Element element, Side side) {
    return edit(network, [&](Network& copy) -> EditResult {
        Rung* rung = rungAt(copy, at.item);
        if (!rung)
            return {kNoRung};
        return insertRaw(*rung, at.node, Circuit::of(canonical(std::move(element))), side);
    });
}

EditResult insertInParallel(Network& network, const ElementPath& at, Element element,
                            std::size_t seriesParts) {
    return edit(network, [&](Network& copy) -> EditResult {
        Rung* rung = rungAt(copy, at.item);
        if (!rung)
            return {kNoRung};
        Circuit* node = nodeAt(*rung, at.node);
        if (!node)
            return {rung->condition ? kNoNode : "a parallel branch needs an element to go around"};
        Circuit branch = Circuit::of(canonical(std::move(element)));
        if (seriesParts == 1) {
            *node = Circuit::parallel({std::move(*node), std::move(branch)});
            return {};
        }
        if (at.node.empty())
            return {"only parts of a series can be taken into a parallel branch together"};
        Circuit* parent = nodeAt(*rung, {at.node.begin(), at.node.end() - 1});
        const std::size_t first = at.node.back();
        if (parent->kind != Circuit::Kind::Series || seriesParts == 0 ||
            first + seriesParts > parent->parts.size())
            return {"only parts of a series can be taken into a parallel branch together"};
        auto begin = parent->parts.begin() + static_cast<std::ptrdiff_t>(first);
        auto end = begin + static_cast<std::ptrdiff_t>(seriesParts);
        Circuit taken =
            Circuit::series({std::make_move_iterator(begin), std::make_move_iterator(end)});
        *begin = Circuit::parallel({std::move(taken), std::move(branch)});
        parent->parts.erase(begin + 1, end);
        return {};
    });
}

EditResult removeNode(Network& network, const ElementPath& at) {
    return edit(network, [&](Network& copy) -> EditResult {
        Rung* rung = rungAt(copy, at.item);
        if (!rung)
            return {kNoRung};
        Circuit* node = nodeAt(*rung, at.node);
        if (!node)
            return {kNoNode};
        *node = placeholder();
        return {};
    });
}

EditResult replaceElement(Network& network, const ElementPath& at, Element element) {
    return edit(network, [&](Network& copy) -> EditResult {
        Rung* rung = rungAt(copy, at.item);
        if (!rung)
            return {kNoRung};
        Circuit* node = nodeAt(*rung, at.node);
        if (!node || !node->isElement())
            return {kNoNode};
        node->element = canonical(std::move(element));
        return {};
    });
}

EditResult moveNode(Network& from, const ElementPath& node, Network& to, const ElementPath& target,
                    Side side) {
    const bool sameNetwork = &from == &to;
    const bool intoItself = sameNetwork && node.item == target.item &&
                            target.node.size() >= node.node.size() &&
                            std::equal(node.node.begin(), node.node.end(), target.node.begin());
    if (intoItself)
        return {"an element cannot be moved next to itself or into itself"};
    Network source = from;
    Network destination = sameNetwork ? Network{} : to;
    Network& targetNetwork = sameNetwork ? source : destination;
    Rung* sourceRung = rungAt(source, node.item);
    if (!sourceRung)
        return {kNoRung};
    Circuit* moved = nodeAt(*sourceRung, node.node);
    if (!moved)
        return {kNoNode};
    Circuit part = std::exchange(*moved, placeholder());
    Rung* targetRung = rungAt(targetNetwork, target.item);
    if (!targetRung)
        return {kNoRung};
    if (EditResult result = insertRaw(*targetRung, target.node, std::move(part), side);
        !result.done())
        return result;
    if (EditResult result = settle(source); !result.done())
        return result;
    if (!sameNetwork)
        if (EditResult result = settle(destination); !result.done())
            return result;
    from = std::move(source);
    if (!sameNetwork)
        to = std::move(destination);
    return {};
}

EditResult copyNode(const Network& from, const ElementPath& node, Network& to,
                    const ElementPath& target, Side side) {
    Network source = from;
    Rung* sourceRung = rungAt(source, node.item);
    if (!sourceRung)
        return {kNoRung};
    const Circuit* copied = nodeAt(*sourceRung, node.node);
    if (!copied)
        return {kNoNode};
    Circuit part = *copied;
    return edit(to, [&](Network& copy) -> EditResult {
        Rung* targetRung = rungAt(copy, target.item);
        if (!targetRung)
            return {kNoRung};
        return insertRaw(*targetRung, target.node, std::move(part), side);
    });
}

EditResult insertRung(Network& network, std::size_t item, Rung rung) {
    return edit(network, [&](Network& copy) -> EditResult {
        if (item > copy.items.size())
            return {kNoRung};
        if (rung.outputs.empty())
            return {"a rung needs an output"};
        copy.items.insert(copy.items.begin() + static_cast<std::ptrdiff_t>(item), std::move(rung));
        return {};
    });
}

EditResult removeItem(Network& network, std::size_t item) {
    return edit(network, [&](Network& copy) -> EditResult {
        if (item >= copy.items.size())
            return {"there is nothing there"};
        copy.items.erase(copy.items.begin() + static_cast<std::ptrdiff_t>(item));
        return {};
    });
}

EditResult addOutput(Network& network, std::size_t item, Output output) {
    return edit(network, [&](Network& copy) -> EditResult {
        Rung* rung = rungAt(copy, item);
        if (!rung)
            return {kNoRung};
        rung->outputs.push_back(std::move(output));
        return {};
    });
}

EditResult replaceOutput(Network& network, std::size_t item, std::size_t index, Output output) {
    return edit(network, [&](Network& copy) -> EditResult {
        Rung* rung = rungAt(copy, item);
        if (!rung || index >= rung->outputs.size())
            return {"there is no output there"};
        rung->outputs[index] = std::move(output);
        return {};
    });
}

EditResult removeOutput(Network& network, std::size_t item, std::size_t index) {
    return edit(network, [&](Network& copy) -> EditResult {
        Rung* rung = rungAt(copy, item);
        if (!rung || index >= rung->outputs.size())
            return {"there is no output there"};
        rung->outputs.erase(rung->outputs.begin() + static_cast<std::ptrdiff_t>(index));
        if (rung->outputs.empty())
            copy.items.erase(copy.items.begin() + static_cast<std::ptrdiff_t>(item));
        return {};
    });
}

} // namespace rs::ladder
