// SPDX-License-Identifier: GPL-3.0-or-later
#include "CursorNavigation.h"

#include <algorithm>
#include <cmath>

namespace rs::ladder {

namespace {

bool startsWith(const std::vector<std::size_t>& path, const std::vector<std::size_t>& prefix) {
    return path.size() >= prefix.size() && std::equal(prefix.begin(), prefix.end(), path.begin());
}

Cursor networkCursor(int step, int network) {
    return {step, network, std::nullopt, std::nullopt, -1};
}

int networkCount(const LaidOutPage& page, int step) {
    return step >= 0 && step < static_cast<int>(page.size()) ? static_cast<int>(page[step].size())
                                                             : 0;
}

// The next network before (-1) or after (1) the cursor's, across steps; the
// cursor itself when there is none.
Cursor neighbourNetwork(const LaidOutPage& page, const Cursor& cursor, int direction) {
    const int steps = static_cast<int>(page.size());
    int step = cursor.step;
    int network = cursor.network + direction;
    while (step >= 0 && step < steps && (network < 0 || network >= networkCount(page, step))) {
        step += direction;
        if (step >= 0 && step < steps)
            network = direction > 0 ? 0 : networkCount(page, step) - 1;
    }
    if (step < 0 || step >= steps)
        return cursor;
    return networkCursor(step, network);
}

// How far an element is in the direction of a move, or -1 when it is not that way.
qreal distance(CursorMove move, const QRectF& here, const ElementLayout& element) {
    const QPointF centre = here.center();
    const QPointF c = element.cell.center();
    const qreal dx = c.x() - centre.x();
    const qreal dy = c.y() - centre.y();
    switch (move) {
    case CursorMove::Left:
        return std::abs(dy) < here.height() / 2 && dx < -1 ? -dx : -1;
    case CursorMove::Right:
        return std::abs(dy) < here.height() / 2 && dx > 1 ? dx : -1;
    case CursorMove::Up:
        return dy < -1 ? -dy * 4 + std::abs(dx) : -1;
    case CursorMove::Down:
        return dy > 1 ? dy * 4 + std::abs(dx) : -1;
    case CursorMove::Out:
    case CursorMove::Network:
        break;
    }
    return -1;
}

} // namespace

Cursor cursorOn(int step, int network, const ElementLayout& element) {
    Cursor cursor = networkCursor(step, network);
    if (element.output >= 0) {
        cursor.output = element.path;
        cursor.outputIndex = element.output;
    } else {
        cursor.node = element.path;
    }
    return cursor;
}

const ElementLayout* elementUnder(const NetworkLayout& layout, const Cursor& cursor) {
    if (cursor.wholeNetwork())
        return nullptr;
    for (const auto& element : layout.elements) {
        if (cursor.node && element.output < 0 && element.path == *cursor.node)
            return &element;
        if (cursor.output && element.output == cursor.outputIndex &&
            element.path.item == cursor.output->item)
            return &element;
    }
    return nullptr;
}

const Circuit* nodeAt(const Network& network, const ElementPath& path) {
    if (path.item >= network.items.size())
        return nullptr;
    const auto* rung = std::get_if<Rung>(&network.items[path.item]);
    if (!rung || !rung->condition)
        return nullptr;
    const Circuit* node = &*rung->condition;
    for (std::size_t index : path.node) {
        if (index >= node->parts.size())
            return nullptr;
        node = &node->parts[index];
    }
    return node;
}

QRectF groupCell(const NetworkLayout& layout, const ElementPath& path) {
    QRectF rect;
    for (const auto& element : layout.elements)
        if (element.output < 0 && element.path.item == path.item &&
            startsWith(element.path.node, path.node))
            rect = rect.united(element.cell);
    return rect;
}

std::optional<Cursor> movedCursor(const LaidOutPage& page, const Cursor& cursor, CursorMove move) {
    if (move == CursorMove::Out) {
        if (!cursor.node || cursor.node->node.empty())
            return std::nullopt;
        Cursor out = cursor;
        out.node->node.pop_back();
        return out;
    }
    if (move == CursorMove::Network)
        return cursor.valid() ? std::optional(networkCursor(cursor.step, cursor.network))
                              : std::nullopt;
    if (!cursor.valid() || cursor.network >= networkCount(page, cursor.step)) {
        if (networkCount(page, 0) > 0)
            return networkCursor(0, 0);
        return std::nullopt;
    }
    const LaidOutNetwork& here = page[cursor.step][cursor.network];
    static const NetworkLayout kNothing;
    const NetworkLayout& layout = here.layout ? *here.layout : kNothing;
    const auto& elements = layout.elements;
    if (cursor.wholeNetwork()) {
        if ((move == CursorMove::Down || move == CursorMove::Right) && !here.collapsed &&
            !elements.empty())
            return cursorOn(cursor.step, cursor.network, elements.front());
        if (move == CursorMove::Down || move == CursorMove::Up)
            return neighbourNetwork(page, cursor, move == CursorMove::Down ? 1 : -1);
        return std::nullopt;
    }
    QRectF cell;
    if (const ElementLayout* element = elementUnder(layout, cursor))
        cell = element->cell;
    else if (cursor.node)
        cell = groupCell(layout, *cursor.node);
    const ElementLayout* best = nullptr;
    qreal bestDistance = 0;
    for (const auto& element : elements) {
        const qreal d = distance(move, cell, element);
        if (d >= 0 && (!best || d < bestDistance)) {
            best = &element;
            bestDistance = d;
        }
    }
    if (best)
        return cursorOn(cursor.step, cursor.network, *best);
    if (move == CursorMove::Up)
        return networkCursor(cursor.step, cursor.network);
    if (move == CursorMove::Down)
        return neighbourNetwork(page, cursor, 1);
    return std::nullopt;
}

} // namespace rs::ladder
