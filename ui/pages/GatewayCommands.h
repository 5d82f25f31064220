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

// The Project menu's gateway commands: New Gateway (its type and node
// address) and Remove Gateway, each one undo step of the project.
class GatewayCommands : public QObject {
    Q_OBJECT
public:
    struct Actions {
        QAction* newGateway = nullptr;
        QAction* removeGateway = nullptr;
    };

    // Dialogs open over `window`; the commands act on the page `current` gives.
    GatewayCommands(QWidget* window, std::function<PageRef()> current);

    const Actions& actions() const { return m_actions; }
    void updateActions(const PageRef& current);

    void newGateway(ProjectDocument* document);
    void removeGateway(ProjectDocument* document, int node);

signals:
    // A gateway was added: the window shows its page.
    void gatewayAdded(ProjectDocument* document, int node);
    // A gateway is about to go: the window leaves its page.
    void gatewayRemoving(ProjectDocument* document, int node);

private:
    QWidget* m_window;
    std::function<PageRef()> m_current;
    Actions m_actions;
};

} // namespace rs::ui
