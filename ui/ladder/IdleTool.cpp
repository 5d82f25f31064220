// SPDX-License-Identifier: GPL-3.0-or-later
#include "IdleTool.h"

#include "DragTool.h"
#include "LadderPage.h"

#include "NetworkItem.h"
#include "document/ProjectDocument.h"

namespace rs::ui {

void IdleTool::pressed(const QPointF& at, Qt::MouseButton button, Qt::KeyboardModifiers modifiers) {
    if (button == Qt::LeftButton && (m_page.toggleCollapseAt(at) || m_page.toggleOptionAt(at)))
        return;
    m_page.select(at, button, modifiers);
}

void IdleTool::doubleClicked(const QPointF& at) {
    m_page.openAt(at);
}

void IdleTool::menuRequested(const QPointF&, const QPoint& globalPosition) {
    m_page.showEditMenu(globalPosition);
}

void IdleTool::dragStarted(const QPointF& from) {
    m_page.dragFrom(from, *this);
}

void IdleTool::toggle() {
    m_page.toggleConfigOption(m_page.cursor().step, m_page.cursor().network);
}

void IdleTool::openProperties() {
    m_page.openSelected();
}

} // namespace rs::ui
