// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/SignatureLabel.h"

#include "compiler/Signature.h"
#include "document/ProjectDocument.h"
#include "output/SettledCompile.h"

namespace rs::ui {

SignatureLabel::SignatureLabel(QWidget* parent) : QLabel(parent) {
    setTextInteractionFlags(Qt::TextSelectableByMouse);
    setToolTip(tr("Changes exactly when what the program does changes; formatting, comments, "
                  "names and descriptions leave it as it is"));
}

void SignatureLabel::setSource(ProjectDocument* document, int station) {
    if (m_compile)
        disconnect(m_compile, nullptr, this, nullptr);
    m_compile = document ? SettledCompile::of(document) : nullptr;
    m_station = station;
    clear();
    if (!m_compile)
        return;
    m_compile->addViewer(this);
    connect(m_compile, &SettledCompile::outdated, this, &SignatureLabel::showOutcome);
    connect(m_compile, &SettledCompile::computed, this, &SignatureLabel::showOutcome);
    showOutcome();
}

bool SignatureLabel::isComputing() const {
    return m_compile && m_compile->isComputing();
}

void SignatureLabel::showOutcome() {
    const SettledCompile::Outcome* outcome = m_compile->outcome();
    if (!outcome) {
        setText(tr("computing..."));
        return;
    }
    const auto unit = outcome->unitSignatures.find(m_station);
    if (!outcome->ok)
        setText(tr("none while the project has errors (Build > Compile shows them)"));
    else if (m_station == kProject)
        setText(QString::fromStdString(compiler::signatureText(outcome->projectSignature)));
    else if (unit != outcome->unitSignatures.end())
        setText(QString::fromStdString(compiler::signatureText(unit->second)));
    else
        clear();
}

} // namespace rs::ui
