// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Cursor.h"
#include "Layout.h"

#include <optional>
#include <vector>

namespace rs::ladder {

// A ladder page as the keyboard walks it: for each step, its networks as laid
// out, and whether a network is collapsed to its title.
struct LaidOutNetwork {
    const NetworkLayout* layout = nullptr;
    bool collapsed = false;
};
using LaidOutPage = std::vector<std::vector<LaidOutNetwork>>;

enum class CursorMove {
    Left,    // the nearest element on the same row to the left
    Right,   // ... to the right (the output after the last contact)
    Up,      // the nearest element above; from the top row, the network itself
    Down,    // the nearest element below; from the bottom row, the next network
    Out,     // the group around the selected node
    Network, // the network the selection is in, as a whole
};

// The cursor on an element of a network (its condition node, or its output).
Cursor cursorOn(int step, int network, const ElementLayout& element);

// The element the cursor stands on in its network's layout, or nullptr (a
// whole network, a group of several elements).
const ElementLayout* elementUnder(const NetworkLayout& layout, const Cursor& cursor);

// The condition node at a path of a network, or nullptr.
const Circuit* nodeAt(const Network& network, const ElementPath& path);

// The cells of a node's elements together, in network coordinates; empty
// when no element is under the path.
QRectF groupCell(const NetworkLayout& layout, const ElementPath& path);

// Where the cursor goes on the page; nullopt where it stays as it is. Without
// a selection any move selects the page's first network.
std::optional<Cursor> movedCursor(const LaidOutPage& page, const Cursor& cursor, CursorMove move);

} // namespace rs::ladder
