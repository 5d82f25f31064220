// SPDX-License-Identifier: GPL-3.0-or-later
#include "LadderTool.h"

#include "LadderPage.h"

#include "document/ProjectDocument.h"

namespace rs::ui {

void LadderTool::dropped(const QPointF& at, const QByteArray& payload, bool move) {
    m_page.dropElement(at, payload, move); // refused where the page does not edit
}

} // namespace rs::ui
