// SPDX-License-Identifier: GPL-3.0-or-later
#include "ScenarioResultsView.h"

#include "shell/StatusColors.h"

#include <QDir>
#include <QFileInfo>
#include <QHeaderView>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace rs::ui {

namespace {

constexpr int kPathRole = Qt::UserRole;
constexpr int kLineRole = Qt::UserRole + 1;

} // namespace

ScenarioResultsView::ScenarioResultsView(QWidget* parent)
    : QWidget(parent), m_tree(new QTreeWidget(this)) {
    m_tree->setObjectName(QStringLiteral("scenarioResults"));
    m_tree->setHeaderHidden(true);
    m_tree->setRootIsDecorated(true);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_tree);
    connect(m_tree, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
        const int line = item->data(0, kLineRole).toInt();
        if (line > 0)
            emit lineActivated(item->data(0, kPathRole).toString(), line);
    });
}

void ScenarioResultsView::addResult(const SimulationSession::ScenarioResult& result) {
    auto* run = new QTreeWidgetItem;
    const QString file = QFileInfo(result.path).fileName();
    run->setToolTip(0, QDir::toNativeSeparators(result.path));
    if (!result.error.isEmpty()) {
        run->setText(0, tr("%1: %2").arg(file, result.error));
        run->setForeground(0, errorTextColor(palette()));
    } else if (result.cancelled) {
        run->setText(0, tr("%1: cancelled at t = %2 s, %3 passed, %4 failed so far")
                            .arg(file)
                            .arg(static_cast<double>(result.endMs) / 1000.0, 0, 'f', 3)
                            .arg(result.passed)
                            .arg(result.failed));
        run->setForeground(0, errorTextColor(palette()));
    } else {
        run->setText(
            0, tr("%1: %2 passed, %3 failed").arg(file).arg(result.passed).arg(result.failed));
        run->setForeground(0, result.failed ? errorTextColor(palette()) : passTextColor(palette()));
    }
    for (const auto& failure : result.failures) {
        auto* line = new QTreeWidgetItem(run);
        line->setText(0, failure.text);
        line->setData(0, kPathRole, result.path);
        line->setData(0, kLineRole, failure.line);
        line->setToolTip(0, tr("Double-click to show line %1 of %2").arg(failure.line).arg(file));
        line->setForeground(0, errorTextColor(palette()));
    }
    m_tree->insertTopLevelItem(0, run);
    run->setExpanded(true);
    // The first failure is chosen, so Enter shows it; a run that passed stays
    // unchosen, keeping its colour visible.
    m_tree->setCurrentItem(run->childCount() > 0 ? run->child(0) : nullptr);
}

} // namespace rs::ui
