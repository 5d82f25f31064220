// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "shell/PageRef.h"

#include <QHash>
#include <QIcon>
#include <QTreeWidget>

#include <vector>

namespace rs::ui {

class ProjectDocument;

// The tree at the left of the window (manual Part 1, 4): Projects, each open
// project, its units ("Pluto 3 — B46"), and under each unit its I/O Options,
// Variables, PLC Code and sequences; the project's gateways and its Properties. Choosing a node
// asks for its page; a right click asks for its context menu.
class ProjectTree : public QTreeWidget {
    Q_OBJECT
public:
    explicit ProjectTree(QWidget* parent = nullptr);

    // Rebuilds the nodes, keeping which were expanded and which is current.
    void setDocuments(const std::vector<ProjectDocument*>& documents);
    // Makes the node of the page current, without asking for the page again.
    void select(const PageRef& page);
    QTreeWidgetItem* itemFor(const PageRef& page) const;
    static PageRef pageOf(const QTreeWidgetItem* item);

signals:
    void pageRequested(const PageRef& page);
    void menuRequested(const PageRef& page, const QPoint& globalPosition);

private:
    QTreeWidgetItem* add(QTreeWidgetItem* parent, const QString& text, const QString& icon,
                         const PageRef& page);
    void updateProjectItem(ProjectDocument* document);

    std::vector<ProjectDocument*> m_documents;
    bool m_selecting = false;
    QHash<QString, QIcon> m_icons; // read once: the tree is made anew after most edits
};

} // namespace rs::ui
