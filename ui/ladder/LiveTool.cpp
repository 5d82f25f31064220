// SPDX-License-Identifier: GPL-3.0-or-later
#include "LiveTool.h"

#include "LadderPage.h"

#include "document/ProjectDocument.h"

namespace rs::ui {

void LiveTool::pressed(const QPointF& at, Qt::MouseButton button, Qt::KeyboardModifiers) {
    if (button == Qt::LeftButton && m_page.toggleCollapseAt(at))
        return;
    m_page.pointAt(at);
    if (button == Qt::LeftButton)
        m_page.reportOperand();
}

void LiveTool::menuRequested(const QPointF& at, const QPoint& globalPosition) {
    m_page.pointAt(at);
    m_page.reportOperandMenu(globalPosition);
}

void LiveTool::toggle() {
    m_page.reportOperand();
}

void LiveTool::openOperandMenu() {
    m_page.reportOperandMenu();
}

} // namespace rs::ui
