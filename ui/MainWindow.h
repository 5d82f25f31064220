#pragma once

#include "RecentFiles.h"
#include "lang/Diagnostic.h"

#include <QMainWindow>
#include <QTimer>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QToolBar;

namespace rs::ui {

class ProblemsView;
class ProgramEditor;

// The IDE window: the program text in the middle, the checker's findings in
// the Problems dock, and the file and edit commands.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // How long typing must pause before the text is checked again.
    static constexpr int kCheckDelayMs = 300;

    explicit MainWindow(QWidget* parent = nullptr);

    // Loads a project file without asking anything and without recording it
    // among the recent files. Returns the error message, empty on success.
    QString loadFile(const QString& path);

    // Loads a project file the way the Open command does: unsaved changes are
    // offered for saving first, a file that cannot be read is reported in a
    // message box and the current text stays, a file read joins the recent files.
    bool openFile(const QString& path);

    // Shows the example project bundled with the IDE, as an unsaved file.
    void showExample();

    // Shows the program text of the unit with this station number. False when
    // the project has no such unit.
    bool showUnit(int station);

    // Window size, position and dock layout as the user left them.
    void restoreLayout();

    ProgramEditor* editor() const { return m_editor; }

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void createActions();
    void createMenus();
    void createToolBar();
    void createProblemsDock();
    void createStatusBar();

    void newProject();
    void open();
    bool save();
    bool saveAs();
    bool saveTo(const QString& path);
    void formatDocument();
    void about();

    bool maybeSave();
    void showText(const QByteArray& text, const QString& path, const QString& displayName);
    void updateTitle();
    void fillRecentMenu();
    void updateEditActions();

    // Checks the text now and shows the findings.
    void check();
    void showSummary(const lang::Diagnostics& diagnostics);

    ProgramEditor* m_editor;
    ProblemsView* m_problems = nullptr;
    QDockWidget* m_problemsDock = nullptr;
    QLabel* m_summary = nullptr;
    QLabel* m_position = nullptr;
    QMenu* m_recentMenu = nullptr;
    QToolBar* m_fileToolBar = nullptr;
    QTimer m_checkTimer;
    RecentFiles m_recentFiles;

    QString m_path; // empty while the text has never been saved
    QString m_displayName;

    QAction* m_newAction = nullptr;
    QAction* m_openAction = nullptr;
    QAction* m_saveAction = nullptr;
    QAction* m_saveAsAction = nullptr;
    QAction* m_quitAction = nullptr;
    QAction* m_undoAction = nullptr;
    QAction* m_redoAction = nullptr;
    QAction* m_cutAction = nullptr;
    QAction* m_copyAction = nullptr;
    QAction* m_pasteAction = nullptr;
    QAction* m_selectAllAction = nullptr;
    QAction* m_formatAction = nullptr;
    QAction* m_exampleAction = nullptr;
    QAction* m_aboutAction = nullptr;
};

} // namespace rs::ui
