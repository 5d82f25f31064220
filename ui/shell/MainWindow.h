// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "document/OpenProjects.h"
#include "output/CompileRun.h"
#include "pages/UnitCommands.h"
#include "shell/PageRef.h"
#include "shell/Preferences.h"

#include <QMainWindow>
#include <QUndoGroup>

#include <vector>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QStackedWidget;
class QToolBar;

namespace rs::lang {
struct Diagnostic;
}
namespace rs::project {
struct TextPlace;
}

namespace rs::ui {

class CompileOutput;
class AsiOptionsPage;
class GatewayCommands;
class GatewayPage;
class IoOptionsPage;
class LadderPage;
class ProblemsView;
class ProgramEditor;
class ProjectDocument;
class ProjectPage;
class ProjectTree;
class PropertiesPage;
class SimulationMode;
class TextPage;
class UnitPage;
class VariablesPage;
class WelcomePage;

// The IDE window (manual Part 1, 4): the project tree at the left with every
// open project, the page of the chosen node in the middle (project, unit,
// I/O options, variables, the code as text), the text checker's Problems and
// the compiler's Output below. Every edit of every page goes through the
// undo stack of its project; Edit > Undo and Redo work on the project shown.
// The window assembles menus, docks and pages and wires them together; the
// projects' life from opening to closing is OpenProjects', the Project menu's
// commands are UnitCommands', compiling is CompileRun's.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // How long typing must pause before the text is read into the project.
    static constexpr int kCheckDelayMs = 300;

    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opening, saving and closing projects (OpenProjects says what each does).
    QString loadFile(const QString& path) { return m_projects->loadFile(path); }
    bool openFile(const QString& path) { return m_projects->openFile(path); }
    void showExample() { m_projects->showExample(); }
    bool saveDocument(ProjectDocument* document) { return m_projects->save(document); }
    bool saveDocumentAs(ProjectDocument* document, const QString& path = {}) {
        return m_projects->saveAs(document, path);
    }
    bool closeDocument(ProjectDocument* document) { return m_projects->close(document); }
    bool exportProgramText(ProjectDocument* document, const QString& path = {}) {
        return m_projects->exportProgramText(document, path);
    }
    void autosaveNow() { m_projects->autosaveNow(); }
    int recoverAutosaved() { return m_projects->recoverAutosaved(); }

    // Shows a page of the current project: the code (text) of a unit, its
    // unit page, I/O options or variables, or the project page (any station).
    // False when there is no such unit.
    bool showUnit(int station);
    // A sequence (1-9) of the unit's code, for Code and Ladder; false when it has none.
    bool showPage(PageRef::Kind kind, int station, int sequence = 0);
    // Shows any page; false when the user keeps editing a text with errors.
    bool showPage(const PageRef& page);
    PageRef currentPage() const { return m_current; }
    // What Project > Compare With... opens once `oldPath` is chosen, and
    // Compare With Validated with `oldPath` empty: a comparison's dialog.
    void openComparison(ProjectDocument* document, const QString& oldPath);

    ProjectDocument* currentDocument() const;
    const std::vector<ProjectDocument*>& documents() const { return m_projects->documents(); }

    // Builds the current project off the window's thread.
    void compile();
    bool isCompiling() const { return m_compileRun->isRunning(); }
    // Build > Prove All: the current project's properties page, proving them all.
    void proveAll();

    // Window size, position and dock layout as the user left them.
    void restoreLayout();

    ProgramEditor* editor() const;
    TextPage* textPage() const { return m_textPage; }
    LadderPage* ladderPage() const { return m_ladderPage; }
    ProjectPage* projectPage() const { return m_projectPage; }
    UnitPage* unitPage() const { return m_unitPage; }
    IoOptionsPage* ioOptionsPage() const { return m_ioPage; }
    AsiOptionsPage* asiOptionsPage() const { return m_asiPage; }
    GatewayPage* gatewayPage() const { return m_gatewayPage; }
    VariablesPage* variablesPage() const { return m_variablesPage; }
    PropertiesPage* propertiesPage() const { return m_propertiesPage; }
    ProjectTree* projectTree() const { return m_tree; }
    CompileOutput* compileOutput() const { return m_output; }
    SimulationMode* simulation() const { return m_simulation; }

signals:
    // Another page is shown (or the same page of another unit or project).
    void pageChanged();

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    // The projects' and the Project menu's commands, and what the window shows after them.
    void createCommands();
    void createActions();
    void createMenus();
    void createToolBar();
    void createDocks();
    void createStatusBar();

    void documentAdded(ProjectDocument* document);
    void documentRemoved(ProjectDocument* document);
    void rebuildTree();
    // A unit's code shows as ladder, or as text with Kind::Code.
    void showFirstPageOf(ProjectDocument* document, PageRef::Kind codeView = PageRef::Kind::Ladder);

    bool leaveTextPage();
    void undo();
    void redo();
    void formatDocument();
    void editPreferences();
    void about();
    void showTreeMenu(const PageRef& page, const QPoint& globalPosition);
    void showCompilePlace(const project::TextPlace& place, int column);

    void updateTitle();
    void updateActions();
    void showSummary(const std::vector<lang::Diagnostic>& diagnostics);
    void showMessage(const QString& message);

    PageRef m_current;
    QUndoGroup m_undoGroup;
    Preferences m_preferences;
    OpenProjects* m_projects = nullptr;
    UnitCommands* m_units = nullptr;
    GatewayCommands* m_gateways = nullptr;
    CompileRun* m_compileRun = nullptr;

    QStackedWidget* m_pages = nullptr;
    WelcomePage* m_welcomePage = nullptr;
    ProjectPage* m_projectPage = nullptr;
    UnitPage* m_unitPage = nullptr;
    IoOptionsPage* m_ioPage = nullptr;
    AsiOptionsPage* m_asiPage = nullptr;
    GatewayPage* m_gatewayPage = nullptr;
    VariablesPage* m_variablesPage = nullptr;
    TextPage* m_textPage = nullptr;
    LadderPage* m_ladderPage = nullptr;
    PropertiesPage* m_propertiesPage = nullptr;
    ProjectTree* m_tree = nullptr;
    ProblemsView* m_problems = nullptr;
    CompileOutput* m_output = nullptr;
    SimulationMode* m_simulation = nullptr;
    QDockWidget* m_treeDock = nullptr;
    QDockWidget* m_problemsDock = nullptr;
    QDockWidget* m_outputDock = nullptr;
    QLabel* m_summary = nullptr;
    QLabel* m_position = nullptr;
    QMenu* m_recentMenu = nullptr;
    QToolBar* m_fileToolBar = nullptr;

    QAction* m_quitAction = nullptr;
    QAction* m_undoAction = nullptr;
    QAction* m_redoAction = nullptr;
    QAction* m_cutAction = nullptr;
    QAction* m_copyAction = nullptr;
    QAction* m_pasteAction = nullptr;
    QAction* m_selectAllAction = nullptr;
    QAction* m_formatAction = nullptr;
    QAction* m_markValidatedAction = nullptr;
    QAction* m_compareAction = nullptr;
    QAction* m_compareValidatedAction = nullptr;
    QAction* m_codeViewAction = nullptr; // between the code's ladder and its text
    QAction* m_preferencesAction = nullptr;
    QAction* m_compileAction = nullptr;
    QAction* m_proveAllAction = nullptr;
    QAction* m_aboutAction = nullptr;
};

} // namespace rs::ui
