// SPDX-License-Identifier: GPL-3.0-or-later
#include "LadderPage.h"

#include "document/ProjectDocument.h"
#include "ladder/ElementProblems.h"

namespace rs::ui {

void LadderPage::setDiagnostics(const lang::Diagnostics& diagnostics) {
    m_drawing.problems.clear();
    if (m_document)
        for (const auto& [element, text] :
             ladder::problemsByElement(m_document->project(), m_station, diagnostics))
            m_drawing.problems[{element.statement, element.element}] = QString::fromStdString(text);
    repaintItems();
}

} // namespace rs::ui
