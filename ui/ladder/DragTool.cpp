// SPDX-License-Identifier: GPL-3.0-or-later
#include "DragTool.h"

#include "LadderPage.h"

#include "document/ProjectDocument.h"

namespace rs::ui {

void DragTool::run(const QPointF& from, LadderTool& resume) {
    m_resume = &resume;
    m_page.setTool(*this);
    m_page.dragElement(from);
    m_page.setTool(*m_resume);
    m_resume = nullptr;
}

const EditSession* DragTool::editSession() const {
    return m_resume ? m_resume->editSession() : nullptr;
}

void DragTool::endEditSession() {
    m_resume = &m_page.restingTool();
}

} // namespace rs::ui
