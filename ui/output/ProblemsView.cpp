// SPDX-License-Identifier: GPL-3.0-or-later
#include "output/ProblemsView.h"

#include <QHeaderView>
#include <QIcon>
#include <QPainter>

namespace rs::ui {

namespace {

constexpr int kLineRole = Qt::UserRole;
constexpr int kColumnRole = Qt::UserRole + 1;

} // namespace

ProblemsView::ProblemsView(QWidget* parent) : QTreeWidget(parent) {
    setColumnCount(2);
    setHeaderLabels({tr("Location"), tr("Message")});
    setRootIsDecorated(false);
    setUniformRowHeights(true);
    setSelectionMode(SingleSelection);
    setTextElideMode(Qt::ElideRight);
    header()->setStretchLastSection(true);
    header()->setSectionResizeMode(LocationColumn, QHeaderView::ResizeToContents);
    connect(this, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
        emit problemActivated(item->data(LocationColumn, kLineRole).toInt(),
                              item->data(LocationColumn, kColumnRole).toInt());
    });
}

void ProblemsView::setDiagnostics(const lang::Diagnostics& diagnostics) {
    const QIcon errorIcon(QStringLiteral(":/icons/error.svg"));
    const QIcon warningIcon(QStringLiteral(":/icons/warning.svg"));
    clear();
    QList<QTreeWidgetItem*> items;
    items.reserve(static_cast<qsizetype>(diagnostics.size()));
    for (const auto& diagnostic : diagnostics) {
        const bool error = diagnostic.severity == lang::Severity::Error;
        auto* item = new QTreeWidgetItem;
        item->setIcon(LocationColumn, error ? errorIcon : warningIcon);
        item->setToolTip(LocationColumn, error ? tr("Error") : tr("Warning"));
        if (diagnostic.line > 0)
            item->setText(LocationColumn,
                          QStringLiteral("%1:%2").arg(diagnostic.line).arg(diagnostic.column));
        item->setData(LocationColumn, kLineRole, diagnostic.line);
        item->setData(LocationColumn, kColumnRole, diagnostic.column);
        const QString message = QString::fromStdString(diagnostic.message);
        item->setText(MessageColumn, message);
        item->setToolTip(MessageColumn, message);
        items.append(item);
    }
    addTopLevelItems(items);
}

void ProblemsView::paintEvent(QPaintEvent* event) {
    QTreeWidget::paintEvent(event);
    if (topLevelItemCount() > 0)
        return;
    QPainter painter(viewport());
    painter.setPen(palette().color(QPalette::Disabled, QPalette::Text));
    painter.drawText(viewport()->rect(), Qt::AlignCenter, tr("No problems found."));
}

} // namespace rs::ui
