// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ProofRun.h"

#ifndef Q_MOC_RUN
#include "lang/Diagnostic.h"
#endif

#include <QPointer>
#include <QTimer>
#include <QWidget>

#include <optional>

class QAction;
class QLabel;
class QProgressBar;
class QPushButton;
class QToolBar;

namespace rs::ui {

class PageTitle;
class ProjectDocument;
class PropertyEditor;
class ProofResultsView;

// A project's properties (docs/ide.md, "Properties"): the text of the .prop
// file beside the project, edited here and saved with it, read again when
// typing pauses with its errors marked where they are; and Prove All's
// results below it, a row per property. A failed property's counterexample
// (a cover's witness) opens in the simulator.
class PropertiesPage : public QWidget {
    Q_OBJECT
public:
    static constexpr int kReadDelayMs = 300;

    explicit PropertiesPage(QWidget* parent = nullptr);

    void showProject(ProjectDocument* document);
    ProjectDocument* document() const { return m_document; }
    PropertyEditor* editor() const { return m_editor; }
    ProofResultsView* results() const { return m_results; }
    // What reading the text found; none for a text without a property yet.
    const lang::Diagnostics& diagnostics() const { return m_diagnostics; }
    // What the page says of the last Prove All, or why it could not start.
    QString statusText() const;

    // Puts the window's Prove All on the page's tool bar.
    void setProveAllAction(QAction* action);
    // Reads the text and proves every property; false (the page says why)
    // when the text has none or has errors, or a proof runs already.
    bool proveAll(const compiler::CheckOptions& options);
    bool isProving() const { return m_run.isRunning(); }
    void cancel() { m_run.cancel(); }
    QAction* cancelAction() const { return m_cancel; }
    QAction* openCounterexampleAction() const { return m_openCounterexample; }

    // A commented example of every kind of line, for a project without properties.
    static QString example();

signals:
    // Open Counterexample on a row with a scenario.
    void counterexampleRequested(rs::ui::ProjectDocument* document,
                                 const rs::ui::PropertyProof& proof);
    // A proof started or ended.
    void provingChanged();

private:
    void readText();
    void updateTitle();
    void updateActions();
    void setStatus(const QString& text, const QColor& color = {});
    void progress(int index, int total);
    void finished(const QString& error, bool cancelled);
    void takeProofs();
    void markOutdated();

    PageTitle* m_title;
    QToolBar* m_toolBar;
    QAction* m_cancel;
    QAction* m_openCounterexample;
    QAction* m_complete;
    QProgressBar* m_progress;
    QAction* m_progressShown; // the bar's place on the tool bar
    QWidget* m_note;          // a text without a property yet: what to write
    QPushButton* m_insertExample;
    QLabel* m_status;
    PropertyEditor* m_editor;
    ProofResultsView* m_results;
    QTimer m_readTimer;
    QPointer<ProjectDocument> m_document;
    bool m_settingText = false;
    lang::Diagnostics m_diagnostics;
    std::optional<prove::PropertyFile> m_file; // read without errors, with a property
    ProofRun m_run;
    QPointer<ProjectDocument> m_provedDocument; // whose results the rows show
    std::size_t m_shownProofs = 0;
    bool m_outdated = false; // the rows are of an older text or project
};

} // namespace rs::ui
