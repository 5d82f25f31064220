// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Diagnostic.h"

#include <QPointer>
#include <QTimer>
#include <QWidget>

namespace rs::ui {

class PageTitle;
class ProgramEditor;
class ProjectDocument;

// The text view of a unit's code in the program editor. What is typed is read
// into the project when typing pauses, as one undo step of the project; the
// text follows every other change of the model. While the text has errors it
// stays in the editor only, and the project keeps the last text without.
//
// A damaged project (a file that reads with errors) is shown here as a whole
// until it reads cleanly.
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

signals:
    void diagnosticsChanged(const lang::Diagnostics& diagnostics);
    // A damaged project has just read cleanly and is a project of units again.
    void repaired(ProjectDocument* document);

private:
    void followModel();
    void setEditorText(const QByteArray& text, bool keepPlace);
    void setDiagnostics(lang::Diagnostics diagnostics);
    void updateTitle();

    PageTitle* m_title;
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
};

} // namespace rs::ui
