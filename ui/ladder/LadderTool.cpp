// SPDX-License-Identifier: GPL-3.0-or-later
#include "LadderTool.h"

namespace rs::ui {

// Only an element dragged from this page drops on it, and only while it drags.
void LadderTool::dropped(const QPointF&, const QByteArray&) {}

} // namespace rs::ui
