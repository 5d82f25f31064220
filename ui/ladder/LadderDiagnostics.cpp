// SPDX-License-Identifier: GPL-3.0-or-later
#include "LadderPage.h"

#include "document/ProjectDocument.h"
#include "ladder/ElementProblems.h"
#include "output/SettledCompile.h"

namespace rs::ui {

void LadderPage::setDiagnostics(const lang::Diagnostics& diagnostics) {
    m_drawing.problems.clear();
    if (m_document)
        for (const auto& [element, text] :
             ladder::problemsByElement(m_document->project(), m_station, diagnostics))
            m_drawing.problems[{element.statement, element.element}] = QString::fromStdString(text);
    repaintItems();
}

void LadderPage::showChangesSinceValidation() {
    m_drawing.sinceValidation.clear();
    m_drawing.validatedOn.clear();
    const SettledCompile::Outcome* outcome = m_compile ? m_compile->outcome() : nullptr;
    if (m_document && m_document->project().baseline && outcome && outcome->sinceValidation) {
        m_drawing.validatedOn = QString::fromStdString(m_document->project().baseline->date);
        // Numbered as the page numbers them (review::editorNetworks); a
        // removed network has no place to mark.
        for (const review::NetworkDifference& network : outcome->sinceValidation->networks) {
            if (network.station != m_station || network.change == review::Pairing::Removed)
                continue;
            for (int step = 0; step < stepCount(); ++step)
                if (m_steps[step].address.sequence == network.step.sequence &&
                    m_steps[step].address.step == network.step.step)
                    m_drawing.sinceValidation[{step, network.number - 1}] =
                        network.change == review::Pairing::Added;
        }
    }
    repaintItems();
}

} // namespace rs::ui
