// SPDX-License-Identifier: GPL-3.0-or-later
#include "Editing.h"

#include <algorithm>
#include <utility>

namespace rs::ladder {

namespace {

const char* const kNoRung = "there is no rung there";
const char* const kNoNode = kNoCircuitNode;
const char* const kShared =
    "a rung with several outputs cannot hold an edge or a timer, nor read what one of its "
    "outputs writes: the text repeats the condition for every output";

Rung* rungAt(Network& network, std::size_t item) {
    if (item >= network.items.size())
        return nullptr;
    return std::get_if<Rung>(&network.items[item]);
}

Circuit* nodeAt(Rung& rung, const std::vector<std::size_t>& path) {
    return ladder::nodeAt(rung.condition, path);
}

Element canonical(Element element) {
    if (auto* contact = std::get_if<Contact>(&element); contact && !isEdge(contact->kind))
        contact->operandNegated = false;
    return element;
}

// Normalizes every condition and joins adjacent rungs the text cannot tell
// apart; refuses a rung the text cannot say.
EditResult settle(Network& network) {
    std::vector<NetworkItem> items;
    for (auto& item : network.items) {
        if (auto* rung = std::get_if<Rung>(&item)) {
            if (network.block)
                return {"a block network holds its block alone: add a network for the rung"};
            normalizeCondition(rung->condition);
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
    return {ladder::insertInSeries(rung.condition, path, std::move(part), side)};
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
        return {ladder::insertInParallel(rung->condition, at.node,
                                         Circuit::of(canonical(std::move(element))), seriesParts)};
    });
}

EditResult removeNode(Network& network, const ElementPath& at) {
    return edit(network, [&](Network& copy) -> EditResult {
        Rung* rung = rungAt(copy, at.item);
        if (!rung)
            return {kNoRung};
        return {ladder::removeNode(rung->condition, at.node)};
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
    Circuit part = std::exchange(*moved, emptyGroup<Element>());
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
