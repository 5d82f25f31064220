// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "shell/PageRef.h"
#include "shell/Preferences.h"
#include "shell/RecentFiles.h"
// Holds core types by value, so their headers come in here; Qt 6.4's moc cannot
// parse the C++20 standard headers they bring in (<concepts>) and needs only the names.
#ifndef Q_MOC_RUN
#include "compiler/Compiler.h"
#include "lang/Diagnostic.h"
#include "project/TextPlace.h"
#endif

#include <QFutureWatcher>
#include <QMainWindow>
#include <QTimer>
#include <QUndoGroup>

#include <string>
#include <vector>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QProgressBar;
class QStackedWidget;
class QToolBar;

namespace rs::ui {

class CompileOutput;
class IoOptionsPage;
class LadderPage;
class ProblemsView;
class ProgramEditor;
class ProjectDocument;
class ProjectPage;
class ProjectTree;
class SimulationMode;
class TextPage;
class UnitPage;
class VariablesPage;

// The IDE window (manual Part 1, 4): the project tree at the left with every
// open project, the page of the chosen node in the middle (project, unit,
// I/O options, variables, the code as text), the text checker's Problems and
// the compiler's Output below. Every edit of every page goes through the
// undo stack of its project; Edit > Undo and Redo work on the project shown.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // How long typing must pause before the text is read into the project.
    static constexpr int kCheckDelayMs = 300;

    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens a project file without asking anything and without recording it
    // among the recent files. Returns the error message, empty on success.
    QString loadFile(const QString& path);
    // Opens a project file the way the Open command does: a file that cannot
    // be read is reported in a message box, a file read joins the recent files.
    bool openFile(const QString& path);
    // Opens the example project bundled with the IDE, as an unsaved project.
    void showExample();
    // A new project, as File > New makes it once its dialog is answered.
    ProjectDocument* createProject(const QString& name, const QString& description,
                                   bool includeSource);

    // Shows a page of the current project: the code (text) of a unit, its
    // unit page, I/O options or variables, or the project page (any station).
    // False when there is no such unit.
    bool showUnit(int station);
    // A sequence (1-9) of the unit's code, for Code and Ladder; false when it has none.
    bool showPage(PageRef::Kind kind, int station, int sequence = 0);
    // Shows any page; false when the user keeps editing a text with errors.
    bool showPage(const PageRef& page);
    PageRef currentPage() const { return m_current; }

    ProjectDocument* currentDocument() const;
    const std::vector<ProjectDocument*>& documents() const { return m_documents; }

    // Saves the project to its file, or asks for one; false when not saved.
    bool saveDocument(ProjectDocument* document);
    // Saves under a new name; without a path, asks for one.
    bool saveDocumentAs(ProjectDocument* document, const QString& path = {});
    // Closes the project, offering to save changes; false when the user cancels.
    bool closeDocument(ProjectDocument* document);
    // Writes the program text alone (File > Export); without a path, asks for one.
    bool exportProgramText(ProjectDocument* document, const QString& path = {});

    // Builds the current project off the window's thread.
    void compile();
    bool isCompiling() const;

    // Writes every modified project's autosave copy now.
    void autosaveNow();
    // Offers the autosave copies that a crash left behind; returns how many were recovered.
    int recoverAutosaved();

    // Window size, position and dock layout as the user left them.
    void restoreLayout();

    ProgramEditor* editor() const;
    TextPage* textPage() const { return m_textPage; }
    LadderPage* ladderPage() const { return m_ladderPage; }
    ProjectPage* projectPage() const { return m_projectPage; }
    UnitPage* unitPage() const { return m_unitPage; }
    IoOptionsPage* ioOptionsPage() const { return m_ioPage; }
    VariablesPage* variablesPage() const { return m_variablesPage; }
    ProjectTree* projectTree() const { return m_tree; }
    CompileOutput* compileOutput() const { return m_output; }
    SimulationMode* simulation() const { return m_simulation; }

signals:
    // Another page is shown (or the same page of another unit or project).
    void pageChanged();

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void createActions();
    void createMenus();
    void createToolBar();
    void createDocks();
    void createStatusBar();

    void addDocument(ProjectDocument* document);
    void removeDocument(ProjectDocument* document);
    void rebuildTree();
    // A unit's code shows as ladder, or as text with Kind::Code.
    void showFirstPageOf(ProjectDocument* document, PageRef::Kind codeView = PageRef::Kind::Ladder);

    void newProject();
    void open();
    bool maybeSave(ProjectDocument* document);
    bool leaveTextPage();
    void undo();
    void redo();
    void formatDocument();
    void newUnit(ProjectDocument* document);
    void newSequence(ProjectDocument* document, int station);
    void removeUnit(ProjectDocument* document, int station);
    void editRemanent(ProjectDocument* document, int station);
    void importCsv(ProjectDocument* document, int station);
    void exportCsv(ProjectDocument* document, int station);
    void editPreferences();
    void about();
    void showTreeMenu(const PageRef& page, const QPoint& globalPosition);
    void showCompilePlace(const project::TextPlace& place, int column);
    void compileFinished();

    void updateTitle();
    void updateActions();
    void fillRecentMenu();
    void showSummary(const lang::Diagnostics& diagnostics);
    void showMessage(const QString& message);

    std::vector<ProjectDocument*> m_documents;
    PageRef m_current;
    QUndoGroup m_undoGroup;
    RecentFiles m_recentFiles;
    Preferences m_preferences;
    QTimer m_autosaveTimer;

    QStackedWidget* m_pages = nullptr;
    QWidget* m_welcomePage = nullptr;
    ProjectPage* m_projectPage = nullptr;
    UnitPage* m_unitPage = nullptr;
    IoOptionsPage* m_ioPage = nullptr;
    VariablesPage* m_variablesPage = nullptr;
    TextPage* m_textPage = nullptr;
    LadderPage* m_ladderPage = nullptr;
    ProjectTree* m_tree = nullptr;
    ProblemsView* m_problems = nullptr;
    CompileOutput* m_output = nullptr;
    SimulationMode* m_simulation = nullptr;
    QDockWidget* m_treeDock = nullptr;
    QDockWidget* m_problemsDock = nullptr;
    QDockWidget* m_outputDock = nullptr;
    QLabel* m_summary = nullptr;
    QLabel* m_position = nullptr;
    QProgressBar* m_progress = nullptr;
    QMenu* m_recentMenu = nullptr;
    QToolBar* m_fileToolBar = nullptr;

    // What the compiler's worker gives back: the findings, and the image
    // written beside the project (its path; or why it could not be).
    struct Compiled {
        compiler::CompileResult result;
        QString imagePath;
        QString imageError;
    };
    QFutureWatcher<Compiled> m_compileWatcher;
    QPointer<ProjectDocument> m_compiling;
    bool m_compileRunning = false; // from Compile until its result is shown
    std::string m_compiledText;

    QAction* m_newAction = nullptr;
    QAction* m_openAction = nullptr;
    QAction* m_saveAction = nullptr;
    QAction* m_saveAsAction = nullptr;
    QAction* m_saveAllAction = nullptr;
    QAction* m_closeAction = nullptr;
    QAction* m_exportTextAction = nullptr;
    QAction* m_quitAction = nullptr;
    QAction* m_undoAction = nullptr;
    QAction* m_redoAction = nullptr;
    QAction* m_cutAction = nullptr;
    QAction* m_copyAction = nullptr;
    QAction* m_pasteAction = nullptr;
    QAction* m_selectAllAction = nullptr;
    QAction* m_formatAction = nullptr;
    QAction* m_codeViewAction = nullptr; // between the code's ladder and its text
    QAction* m_preferencesAction = nullptr;
    QAction* m_newUnitAction = nullptr;
    QAction* m_newSequenceAction = nullptr;
    QAction* m_removeUnitAction = nullptr;
    QAction* m_remanentAction = nullptr;
    QAction* m_importCsvAction = nullptr;
    QAction* m_exportCsvAction = nullptr;
    QAction* m_compileAction = nullptr;
    QAction* m_exampleAction = nullptr;
    QAction* m_aboutAction = nullptr;
};

} // namespace rs::ui
