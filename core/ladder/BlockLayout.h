// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Layout.h"

// The box of a block network, for layoutNetwork.
namespace rs::ladder {

// Places the box, its pins and their operands below `top`, with the left
// rail at `railX`, into `layout`; returns the bottom of what it placed and
// widens `width` to its right edge.
qreal placeBlock(NetworkLayout& layout, const BlockCall& call, const LayoutContext& context,
                 qreal railX, qreal top, qreal& width);

} // namespace rs::ladder
