// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "shell/RecentFiles.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <functional>
#include <vector>

class QAction;
class QMenu;
class QWidget;

namespace rs::ui {

class ProjectDocument;
class TextPage;

// The projects open in a window, from opening to closing: File > New, Open,
// Open Recent, Save, Save As, Save All, Close and Export > Program Text, and
// Help > Open Example Project; the question about unsaved changes; the copies
// written every few minutes (Autosave) and offered back after a crash.
//
// The window keeps what it shows: it learns from the signals that a project
// came or went, or wants showing, and shows the pages.
class OpenProjects : public QObject {
    Q_OBJECT
public:
    // The commands, created once as children of the window; it puts them in
    // its menus, tool bar and welcome page.
    struct Actions {
        QAction* newProject = nullptr;
        QAction* open = nullptr;
        QAction* save = nullptr;
        QAction* saveAs = nullptr;
        QAction* saveAll = nullptr;
        QAction* close = nullptr;
        QAction* exportText = nullptr;
        QAction* protect = nullptr;
        QAction* example = nullptr;
    };

    // Dialogs open over `window`, and projects are its children. Saving and
    // autosaving read the text page's typing into the project first. The
    // commands act on the project `current` gives.
    OpenProjects(QWidget* window, TextPage* textPage, std::function<ProjectDocument*()> current);
    // The projects stay open to the end: their autosave copies stay for
    // recovery, but the locks that said this window had them go.
    ~OpenProjects() override;

    const std::vector<ProjectDocument*>& documents() const { return m_documents; }
    const Actions& actions() const { return m_actions; }
    // Enables the commands for the project shown (none: null).
    void updateActions(const ProjectDocument* current);
    // Lists the recent files in `menu`, numbered, with Clear Menu.
    void fillRecentMenu(QMenu* menu);
    QStringList recentPaths() const { return m_recentFiles.paths(); }

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
    // File > New: asks for the project, then (unitWanted) for its first unit.
    void newProject();
    // File > Open: asks for the file.
    void open();

    // Saves the project to its file, or asks for one; false when not saved.
    bool save(ProjectDocument* document);
    // Saves under a new name; without a path, asks for one.
    bool saveAs(ProjectDocument* document, const QString& path = {});
    // Saves every modified project; stops at the first one not saved.
    void saveAll();
    // Asks whether to save the project's changes; false when the user cancels.
    bool maybeSave(ProjectDocument* document);
    // Closes the project, offering to save changes; false when the user cancels.
    bool close(ProjectDocument* document);
    // File > Password Protect: protects the project, changes its protection
    // or takes it off, as one undoable edit.
    void passwordProtect(ProjectDocument* document);
    // Writes the program text alone (File > Export); without a path, asks for one.
    bool exportProgramText(ProjectDocument* document, const QString& path = {});
    // The window closes: offers to save every modified project. False when the
    // user cancels; otherwise the autosave copies go, as nothing is lost.
    bool prepareToQuit();

    // How often the copies of modified projects are written.
    void setAutosaveInterval(int minutes);
    // Writes every modified project's autosave copy now.
    void autosaveNow();
    // Offers the autosave copies that a crash left behind; returns how many were recovered.
    int recoverAutosaved();

signals:
    // A project joined documents(); the window adds it to its undo group and tree.
    void added(ProjectDocument* document);
    // A project left documents(); it is deleted later.
    void removed(ProjectDocument* document);
    // A project was opened, recovered, or asked for again while open: the
    // window shows its first page.
    void opened(ProjectDocument* document);
    // A new project: the window shows its project page.
    void created(ProjectDocument* document);
    // File > New made a project: the manual's next step is its first unit.
    void unitWanted(ProjectDocument* document);
    // A line for the status bar.
    void message(const QString& message);

private:
    void createActions();
    void add(ProjectDocument* document);
    void remove(ProjectDocument* document);
    // A protected project just opened: says where a change made outside
    // Rungsmith is, or asks for the permission to open it with. False when
    // the user would rather not open it.
    bool askPermission(ProjectDocument* document);

    QWidget* m_window;
    TextPage* m_textPage;
    std::function<ProjectDocument*()> m_current;
    std::vector<ProjectDocument*> m_documents;
    RecentFiles m_recentFiles;
    QTimer m_autosaveTimer;
    Actions m_actions;
};

} // namespace rs::ui
