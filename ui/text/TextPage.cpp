// SPDX-License-Identifier: GPL-3.0-or-later
#include "text/TextPage.h"

#include "document/PermissionNote.h"
#include "document/ProjectDocument.h"
#include "project/ProjectFile.h"
#include "project/UnitText.h"
#include "shell/PageTitle.h"
#include "shell/UnitCaption.h"
#include "text/CodeCheck.h"
#include "text/ProgramEditor.h"

#include <QAction>
#include <QRegularExpression>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>

namespace rs::ui {

namespace {

std::string_view view(const QByteArray& bytes) {
    return {bytes.constData(), static_cast<std::size_t>(bytes.size())};
}

} // namespace

TextPage::TextPage(QWidget* parent)
    : QWidget(parent), m_title(new PageTitle(this)), m_toolBar(new QToolBar(this)),
      m_editor(new ProgramEditor(this)), m_check(new CodeCheck(this)) {
    connect(m_check, &CodeCheck::checked, this, &TextPage::checked);
    m_editor->setObjectName(QStringLiteral("programEditor"));
    m_toolBar->setObjectName(QStringLiteral("textToolBar"));
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    QAction* ladder = m_toolBar->addAction(tr("Ladder"));
    ladder->setObjectName(QStringLiteral("textLadderAction"));
    ladder->setToolTip(tr("Show this code as ladder networks"));
    connect(ladder, &QAction::triggered, this, &TextPage::ladderRequested);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addWidget(m_toolBar);
    layout->addWidget(m_editor, 1);

    m_applyTimer.setSingleShot(true);
    m_applyTimer.setInterval(kApplyDelayMs);
    connect(&m_applyTimer, &QTimer::timeout, this, &TextPage::applyNow);
    connect(m_editor, &QsciScintilla::textChanged, this, [this] {
        if (m_settingText)
            return;
        if (m_document && m_station == kWholeProject)
            m_document->setDamagedText(m_editor->textBytes());
        m_applyTimer.start();
    });
}

void TextPage::showUnit(ProjectDocument* document, int station) {
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_applyTimer.stop();
    m_document = document;
    m_station = station;
    m_hasErrors = false;
    m_check->otherCodeChanged();
    if (!document) {
        setEditorText({}, false);
        setDiagnostics({});
        return;
    }
    connect(document, &ProjectDocument::changed, this, &TextPage::followModel);
    connect(document, &ProjectDocument::pathChanged, this, &TextPage::updateTitle);
    connect(document, &ProjectDocument::permissionChanged, this, &TextPage::updateTitle);
    // The project's undo stack undoes the code too, except in a damaged
    // project, which has none yet.
    m_editor->setProjectUndo(station != kWholeProject);
    if (station == kWholeProject) {
        setEditorText(document->damagedText(), false);
        m_canonical.clear();
        m_shown.clear();
    } else {
        m_canonical = QByteArray::fromStdString(project::unitText(document->project(), station));
        m_shown = m_canonical;
        setEditorText(m_canonical, false);
    }
    updateTitle();
    applyNow();
}

void TextPage::updateTitle() {
    if (!m_document)
        return;
    m_toolBar->setVisible(m_station != kWholeProject);
    if (m_station == kWholeProject) {
        m_title->setTitle(tr("%1 — Project Text").arg(m_document->displayName()));
        m_title->setSubtitle(tr("This file has errors, so it is shown as text until they are "
                                "fixed. Lines with errors could not be shown on the other pages."));
    } else {
        m_title->setTitle(tr("%1 — PLC Code").arg(unitCaption(m_document->project(), m_station)));
        m_title->setSubtitle({});
    }
    // Config Options change on the ladder, where each is a check box.
    const bool readOnly = m_document->permission() != project::Permission::Full;
    m_editor->setReadOnly(readOnly);
    if (readOnly)
        m_title->setSubtitle(permissionNote(m_document->permission()));
}

bool TextPage::showSequence(int sequence) {
    if (sequence == 0) { // the unit's code from its first line: declarations, then sequence 0
        m_editor->goTo(1, 1);
        return true;
    }
    const QString text = QString::fromUtf8(m_editor->textBytes());
    const QRegularExpression header(
        QStringLiteral("^\\s*S0*%1\\.0*%2_\\d+").arg(m_station).arg(sequence),
        QRegularExpression::CaseInsensitiveOption | QRegularExpression::MultilineOption);
    const QRegularExpressionMatch match = header.match(text);
    if (!match.hasMatch())
        return false;
    const int line = static_cast<int>(text.left(match.capturedStart()).count(QLatin1Char('\n')));
    m_editor->goTo(line + 1, 1);
    return true;
}

bool TextPage::applyNow() {
    m_applyTimer.stop();
    if (!m_document)
        return true;
    const QByteArray text = m_editor->textBytes();
    if (m_station == kWholeProject) {
        project::ProjectReadResult read = project::readProject(view(text));
        setDiagnostics(read.diagnostics);
        m_hasErrors = !read.ok();
        if (!m_hasErrors && m_document->isDamaged()) {
            m_document->repair(std::move(read.project));
            emit repaired(m_document);
        }
        return !m_hasErrors;
    }
    project::UnitTextResult read =
        project::readUnitCode(m_document->project(), m_station, view(text));
    setDiagnostics(read.diagnostics);
    m_hasErrors = !read.ok();
    if (m_hasErrors)
        return false;
    if (text != m_shown) {
        m_canonical = QByteArray::fromStdString(project::unitText(read.project, m_station));
        m_shown = text;
        m_applying = true;
        m_document->replaceUnitCode(tr("Edit Code of Pluto %1").arg(m_station), m_station,
                                    read.project);
        m_applying = false;
    }
    checkCode();
    return true;
}

void TextPage::discardChanges() {
    m_applyTimer.stop();
    if (!m_document || m_station == kWholeProject)
        return;
    m_canonical = QByteArray::fromStdString(project::unitText(m_document->project(), m_station));
    m_shown = m_canonical;
    setEditorText(m_canonical, true);
    m_hasErrors = false;
    applyNow();
}

bool TextPage::formatText() {
    if (!applyNow())
        return false;
    QByteArray formatted;
    if (m_station == kWholeProject)
        formatted = m_document->fileText();
    else
        formatted = QByteArray::fromStdString(project::unitText(m_document->project(), m_station));
    if (formatted != m_editor->textBytes()) {
        setEditorText(formatted, true);
        m_shown = formatted;
    }
    return true;
}

void TextPage::followModel() {
    if (m_applying || !m_document || m_station == kWholeProject)
        return;
    m_check->otherCodeChanged(); // undone, redone, or edited on another page
    updateTitle();
    const QByteArray canonical =
        QByteArray::fromStdString(project::unitText(m_document->project(), m_station));
    if (canonical == m_canonical) {
        checkCode(); // another unit changed: what it uses may change the findings
        return;
    }
    // Undo, redo or another page changed this unit: show the project's text.
    m_applyTimer.stop();
    m_canonical = canonical;
    m_shown = canonical;
    setEditorText(canonical, true);
    m_hasErrors = false;
    project::UnitTextResult read =
        project::readUnitCode(m_document->project(), m_station, view(canonical));
    setDiagnostics(read.diagnostics);
    checkCode();
}

void TextPage::setEditorText(const QByteArray& text, bool keepPlace) {
    int line = 0;
    int index = 0;
    m_editor->getCursorPosition(&line, &index);
    const int firstShown = m_editor->firstVisibleLine();
    m_settingText = true;
    m_editor->setTextBytes(text);
    m_settingText = false;
    if (keepPlace) {
        m_editor->setCursorPosition(std::min(line, std::max(m_editor->lines() - 1, 0)), 0);
        m_editor->setFirstVisibleLine(firstShown);
    }
}

void TextPage::setDiagnostics(lang::Diagnostics diagnostics) {
    m_readDiagnostics = diagnostics;
    ++m_checkTicket;
    showDiagnostics(std::move(diagnostics));
}

void TextPage::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    checkCode();
}

void TextPage::checkCode() {
    // The compiler checks the project: text with reading errors is not in it.
    // A hidden page is checked when it shows.
    if (isVisible() && m_document && m_station != kWholeProject &&
        lang::errorCount(m_readDiagnostics) == 0)
        m_check->request(m_document->project(), m_document->path(), m_station, m_checkTicket);
}

void TextPage::showDiagnostics(lang::Diagnostics diagnostics) {
    m_diagnostics = std::move(diagnostics);
    m_editor->setDiagnostics(m_diagnostics);
    emit diagnosticsChanged(m_diagnostics);
}

void TextPage::checked(quint64 ticket, const lang::Diagnostics& diagnostics) {
    if (ticket != m_checkTicket)
        return;
    // The compiler reports the reading's warnings again; each is shown once.
    lang::Diagnostics all = m_readDiagnostics;
    for (const lang::Diagnostic& found : diagnostics)
        if (std::none_of(all.begin(), all.end(), [&](const lang::Diagnostic& known) {
                return known.line == found.line && known.column == found.column &&
                       known.message == found.message;
            }))
            all.push_back(found);
    lang::sortByPlace(all);
    showDiagnostics(std::move(all));
}

bool TextPage::isChecking() const {
    return m_check->isBusy();
}

void TextPage::setWarnUnconfiguredIo(bool warn) {
    m_check->setWarnUnconfiguredIo(warn);
}

} // namespace rs::ui
