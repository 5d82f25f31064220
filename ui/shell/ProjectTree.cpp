// SPDX-License-Identifier: GPL-3.0-or-later
#include "shell/ProjectTree.h"

#include "document/ProjectDocument.h"
#include "project/Sequences.h"
#include "project/UnitSettings.h"
#include "shell/UnitCaption.h"

#include <QFileInfo>
#include <QHeaderView>
#include <QIcon>
#include <QSet>

namespace rs::ui {

namespace {

constexpr int kKindRole = Qt::UserRole;
constexpr int kDocumentRole = Qt::UserRole + 1;
constexpr int kStationRole = Qt::UserRole + 2;
constexpr int kSequenceRole = Qt::UserRole + 3;

// What identifies a node across rebuilds. The code's node stands for its
// ladder and its text alike.
QString keyOf(const PageRef& page) {
    const PageRef::Kind kind = page.kind == PageRef::Kind::Code ? PageRef::Kind::Ladder : page.kind;
    return QStringLiteral("%1/%2/%3/%4")
        .arg(static_cast<int>(kind))
        .arg(reinterpret_cast<quintptr>(page.document.data()))
        .arg(page.station)
        .arg(page.sequence);
}

} // namespace

ProjectTree::ProjectTree(QWidget* parent) : QTreeWidget(parent) {
    setHeaderHidden(true);
    setColumnCount(1);
    setUniformRowHeights(true);
    setContextMenuPolicy(Qt::CustomContextMenu);
    setExpandsOnDoubleClick(true);
    connect(this, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        if (item && !m_selecting)
            emit pageRequested(pageOf(item));
    });
    // The code's node is current while its text is shown too: a click on it shows the ladder.
    connect(this, &QTreeWidget::itemClicked, this, [this](QTreeWidgetItem* item) {
        if (item && !m_selecting)
            emit pageRequested(pageOf(item));
    });
    connect(this, &QWidget::customContextMenuRequested, this, [this](const QPoint& at) {
        QTreeWidgetItem* item = itemAt(at);
        emit menuRequested(item ? pageOf(item) : PageRef{}, viewport()->mapToGlobal(at));
    });
    setDocuments({});
}

PageRef ProjectTree::pageOf(const QTreeWidgetItem* item) {
    PageRef page;
    if (!item)
        return page;
    page.kind = static_cast<PageRef::Kind>(item->data(0, kKindRole).toInt());
    page.document = qobject_cast<ProjectDocument*>(item->data(0, kDocumentRole).value<QObject*>());
    page.station = item->data(0, kStationRole).toInt();
    page.sequence = item->data(0, kSequenceRole).toInt();
    return page;
}

QTreeWidgetItem* ProjectTree::add(QTreeWidgetItem* parent, const QString& text, const QString& icon,
                                  const PageRef& page) {
    auto found = m_icons.find(icon);
    if (found == m_icons.end())
        found = m_icons.insert(icon, QIcon(QStringLiteral(":/icons/%1.svg").arg(icon)));
    auto* item = new QTreeWidgetItem(parent, {text});
    item->setIcon(0, *found);
    item->setData(0, kKindRole, static_cast<int>(page.kind));
    item->setData(0, kDocumentRole, QVariant::fromValue<QObject*>(page.document.data()));
    item->setData(0, kStationRole, page.station);
    item->setData(0, kSequenceRole, page.sequence);
    return item;
}

void ProjectTree::setDocuments(const std::vector<ProjectDocument*>& documents) {
    QSet<QString> expanded;
    for (QTreeWidgetItemIterator it(this); *it; ++it)
        if ((*it)->isExpanded())
            expanded.insert(keyOf(pageOf(*it)));
    const PageRef current = pageOf(currentItem());
    const bool fresh = topLevelItemCount() == 0;
    std::vector<ProjectDocument*> known = m_documents;
    for (ProjectDocument* document : m_documents)
        if (std::find(documents.begin(), documents.end(), document) == documents.end())
            disconnect(document, nullptr, this, nullptr);
    m_documents = documents;

    m_selecting = true;
    clear();
    auto* root = new QTreeWidgetItem(this, {tr("Projects")});
    root->setIcon(0, QIcon(QStringLiteral(":/icons/projects.svg")));
    root->setData(0, kKindRole, static_cast<int>(PageRef::Kind::None));
    for (ProjectDocument* document : documents) {
        const bool isNew = std::find(known.begin(), known.end(), document) == known.end();
        if (isNew) {
            connect(document, &ProjectDocument::modificationChanged, this,
                    [this, document] { updateProjectItem(document); });
            connect(document, &ProjectDocument::pathChanged, this,
                    [this, document] { updateProjectItem(document); });
        }
        QTreeWidgetItem* projectItem =
            add(root, {}, QStringLiteral("project"), {PageRef::Kind::Project, document});
        if (isNew)
            expanded.insert(keyOf(pageOf(projectItem)));
        if (document->isDamaged()) {
            add(projectItem, tr("Project Text"), QStringLiteral("code"),
                {PageRef::Kind::ProjectText, document, -1});
            continue;
        }
        const project::Project& p = document->project();
        for (const auto& unit : project::unitsOf(p)) {
            const int station = unit.station;
            QTreeWidgetItem* unitItem = add(projectItem, unitCaption(unit), QStringLiteral("unit"),
                                            {PageRef::Kind::Unit, document, station});
            if (isNew)
                expanded.insert(keyOf(pageOf(unitItem)));
            add(unitItem, tr("I/O Options"), QStringLiteral("io-options"),
                {PageRef::Kind::IoOptions, document, station});
            if (project::unitTypeOf(p, station).asiSlaves)
                add(unitItem, tr("AS-i Options"), QStringLiteral("asi-options"),
                    {PageRef::Kind::AsiOptions, document, station});
            add(unitItem, tr("Variables"), QStringLiteral("variables"),
                {PageRef::Kind::Variables, document, station});
            add(unitItem, tr("PLC Code"), QStringLiteral("code"),
                {PageRef::Kind::Ladder, document, station, 0});
            for (int sequence : project::sequencesOf(p, station))
                add(unitItem, tr("Sequence %1").arg(sequence), QStringLiteral("sequence"),
                    {PageRef::Kind::Ladder, document, station, sequence});
        }
        for (const auto& [node, gateway] : p.gateways)
            add(projectItem,
                tr("Gateway %1 (%2)")
                    .arg(node)
                    .arg(QString::fromLatin1(project::gatewayTypeName(gateway.type).data())),
                QStringLiteral("gateway"), {PageRef::Kind::Gateway, document, node});
        add(projectItem, tr("Properties"), QStringLiteral("properties"),
            {PageRef::Kind::Properties, document});
        updateProjectItem(document);
    }
    root->setExpanded(true);
    for (QTreeWidgetItemIterator it(this); *it; ++it)
        if (expanded.contains(keyOf(pageOf(*it))) ||
            (fresh && pageOf(*it).kind == PageRef::Kind::Project))
            (*it)->setExpanded(true);
    if (QTreeWidgetItem* item = itemFor(current))
        setCurrentItem(item);
    m_selecting = false;
}

void ProjectTree::updateProjectItem(ProjectDocument* document) {
    QTreeWidgetItem* item = itemFor({PageRef::Kind::Project, document});
    if (!item)
        return;
    // The project's name, and its file when that is named otherwise.
    const QString name = QString::fromStdString(document->project().name());
    const QString file = QFileInfo(document->path()).fileName();
    QString text = name.isEmpty() ? document->displayName()
                   : file.isEmpty() || QFileInfo(file).completeBaseName() == name
                       ? name
                       : tr("%1 (%2)").arg(name, file);
    if (document->isModified())
        text += QStringLiteral(" *");
    item->setText(0, text);
    item->setToolTip(0, document->path());
}

QTreeWidgetItem* ProjectTree::itemFor(const PageRef& page) const {
    if (page.kind == PageRef::Kind::None)
        return nullptr;
    const QString key = keyOf(page);
    for (QTreeWidgetItemIterator it(const_cast<ProjectTree*>(this)); *it; ++it)
        if (keyOf(pageOf(*it)) == key)
            return *it;
    return nullptr;
}

void ProjectTree::select(const PageRef& page) {
    QTreeWidgetItem* item = itemFor(page);
    if (!item)
        return;
    m_selecting = true;
    setCurrentItem(item);
    scrollToItem(item);
    m_selecting = false;
}

} // namespace rs::ui
