// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Diagnostic.h"

#include <QPointer>
#include <QTimer>
#include <QWidget>

class QToolBar;

namespace rs::ui {

class CodeCheck;
class PageTitle;
class ProgramEditor;
class ProjectDocument;

// The text view of a unit's code in the program editor. What is typed is read
// into the project when typing pauses, as one undo step of the project; the
// text follows every other change of the model. While the text has errors it
// stays in the editor only, and the project keeps the last text without.
//
// After the typing pause, the compiler checks the unit too, off the window's
// thread (CodeCheck), and its findings join the reading's in the editor's
// marks and in diagnostics().
//
// A damaged project (a file that reads with errors) is shown here as a whole
// until it reads cleanly. A unit's code has a Ladder button back to its
// ladder page, as the ladder page has a Text button.
class TextPage : public QWidget {
    Q_OBJECT
public:
    static constexpr int kApplyDelayMs = 300;
    static constexpr int kWholeProject = -1;

    explicit TextPage(QWidget* parent = nullptr);

    // The code of the unit with this station, or kWholeProject for a damaged project.
    void showUnit(ProjectDocument* document, int station);
    // Puts the cursor on the first step of the sequence (0: the main code).
    bool showSequence(int sequence);

    ProjectDocument* document() const { return m_document; }
    int station() const { return m_station; }
    ProgramEditor* editor() const { return m_editor; }

    // Reads what was typed into the project now. False when the text has
    // errors, which then are not in the project.
    bool applyNow();
    bool hasErrors() const { return m_hasErrors; }
    // Puts the project's text back, dropping what was typed since it was last read.
    void discardChanges();
    // Rewrites the text in the canonical layout; false when it has errors.
    bool formatText();

    const lang::Diagnostics& diagnostics() const { return m_diagnostics; }
    // The compiler's check of the shown code runs or waits.
    bool isChecking() const;
    void setWarnUnconfiguredIo(bool warn);

signals:
    void diagnosticsChanged(const lang::Diagnostics& diagnostics);
    // A damaged project has just read cleanly and is a project of units again.
    void repaired(ProjectDocument* document);
    // The tool bar's Ladder: the same code as ladder networks.
    void ladderRequested();

protected:
    void showEvent(QShowEvent* event) override;

private:
    void followModel();
    void setEditorText(const QByteArray& text, bool keepPlace);
    // What reading the text found; the compiler's check follows when it read.
    void setDiagnostics(lang::Diagnostics diagnostics);
    void showDiagnostics(lang::Diagnostics diagnostics);
    void checkCode();
    void checked(quint64 ticket, const lang::Diagnostics& diagnostics);
    void updateTitle();

    PageTitle* m_title;
    QToolBar* m_toolBar; // a unit's code only: a damaged project has no ladder
    ProgramEditor* m_editor;
    QTimer m_applyTimer;
    QPointer<ProjectDocument> m_document;
    int m_station = 0;
    QByteArray m_canonical; // the model's text of the unit when it was last shown or read
    QByteArray m_shown;     // the editor's text that the model holds
    bool m_hasErrors = false;
    bool m_settingText = false;
    bool m_applying = false;
    lang::Diagnostics m_diagnostics;
    lang::Diagnostics m_readDiagnostics;
    CodeCheck* m_check;
    quint64 m_checkTicket = 0; // of the text shown; an older check's result is dropped
};

} // namespace rs::ui
