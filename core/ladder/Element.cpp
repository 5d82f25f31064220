// SPDX-License-Identifier: GPL-3.0-or-later
#include "Element.h"

namespace rs::ladder {

bool isEdge(ElementKind kind) {
    return kind == ElementKind::PositiveEdge || kind == ElementKind::NegativeEdge ||
           kind == ElementKind::NotPositiveEdge || kind == ElementKind::NotNegativeEdge;
}

} // namespace rs::ladder
