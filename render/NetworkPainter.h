// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "LadderStyle.h"
#include "PowerSnapshot.h"
#include "ladder/Layout.h"

class QPainter;

namespace rs::render {

// Draws a laid-out network with its top-left corner at the painter's origin,
// in layout units: rails, wires, contacts, coils, boxes, names and addresses,
// the title and comments. With a snapshot, what conducts in it is drawn in
// the style's powered colour and weight; without one, everything is drawn
// as when nothing runs. The GUI's scene and the command line both draw
// through this.
void paintNetwork(QPainter& painter, const ladder::NetworkLayout& layout, const LadderStyle& style,
                  const PowerSnapshot* power = nullptr);

} // namespace rs::render
