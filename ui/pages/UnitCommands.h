// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "shell/PageRef.h"

#include <QObject>
#include <QString>

#include <functional>

class QAction;
class QWidget;

namespace rs::ui {

class ProjectDocument;

// The Project menu (manual Part 1, 10): New Pluto, New Sequence, Remove
// Pluto, Remanent Variables, and Import and Export of variable names (CSV),
// each through its dialog and each change one undo step of the project. The
// project tree's menu and the pages ask for them too, naming the unit.
//
// The window shows the pages; it learns from the signals what to show.
class UnitCommands : public QObject {
    Q_OBJECT
public:
    // The menu's commands, created once as children of the window.
    struct Actions {
        QAction* newUnit = nullptr;
        QAction* newSequence = nullptr;
        QAction* removeUnit = nullptr;
        QAction* remanent = nullptr;
        QAction* importCsv = nullptr;
        QAction* exportCsv = nullptr;
    };

    // Dialogs open over `window`. The menu's commands act on the project and
    // the unit of the page `current` gives.
    UnitCommands(QWidget* window, std::function<PageRef()> current);

    const Actions& actions() const { return m_actions; }
    // Enables the commands for the page shown.
    void updateActions(const PageRef& current);

    void newUnit(ProjectDocument* document);
    void newSequence(ProjectDocument* document, int station);
    void removeUnit(ProjectDocument* document, int station);
    void editRemanent(ProjectDocument* document, int station);
    void importCsv(ProjectDocument* document, int station);
    void exportCsv(ProjectDocument* document, int station);

signals:
    // A unit was added: the window shows its unit page.
    void unitAdded(ProjectDocument* document, int station);
    // A sequence was added: the window shows its code.
    void sequenceAdded(ProjectDocument* document, int station, int sequence);
    // A unit is about to go: the window leaves its pages.
    void unitRemoving(ProjectDocument* document, int station);
    // A line for the status bar.
    void message(const QString& message);

private:
    void createActions();

    QWidget* m_window;
    std::function<PageRef()> m_current;
    Actions m_actions;
};

} // namespace rs::ui
