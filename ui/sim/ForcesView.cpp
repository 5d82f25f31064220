// SPDX-License-Identifier: GPL-3.0-or-later
#include "ForcesView.h"

#include "SimulationSession.h"
#include "document/ProjectDocument.h"
#include "project/VariableTable.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace rs::ui {

namespace {

constexpr int kAddressRole = Qt::UserRole;

} // namespace

ForcesView::ForcesView(SimulationSession* session, QWidget* parent)
    : QWidget(parent), m_session(session), m_table(new QTableWidget(0, 3, this)),
      m_release(new QPushButton(tr("&Release"), this)),
      m_releaseAll(new QPushButton(tr("Release &All"), this)) {
    m_table->setObjectName(QStringLiteral("forcesTable"));
    m_table->setHorizontalHeaderLabels({tr("Variable"), tr("Symbolic Name"), tr("Forced To")});
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->hide();
    // Columns as wide as their heading or longest entry, in any language.
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_release->setObjectName(QStringLiteral("releaseForceButton"));
    m_releaseAll->setObjectName(QStringLiteral("releaseAllForcesButton"));
    m_release->setToolTip(tr("Release the chosen force: the program writes the variable again"));

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_release);
    buttons->addWidget(m_releaseAll);
    buttons->addStretch();
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_table);
    layout->addLayout(buttons);

    connect(m_release, &QPushButton::clicked, this, &ForcesView::releaseSelected);
    connect(m_releaseAll, &QPushButton::clicked, m_session, &SimulationSession::releaseAll);
    connect(m_table, &QTableWidget::itemSelectionChanged, this,
            [this] { m_release->setEnabled(!m_table->selectedItems().isEmpty()); });
    connect(m_session, &SimulationSession::forcesChanged, this, &ForcesView::refresh);
    refresh();
}

void ForcesView::refresh() {
    const auto forces = m_session->forces();
    m_table->setRowCount(static_cast<int>(forces.size()));
    int row = 0;
    for (const auto& [address, value] : forces) {
        const QString spelled = QString::fromStdString(lang::toString(address));
        const QString name = m_session->document() ? QString::fromStdString(project::variableName(
                                                         m_session->document()->project(), address))
                                                   : QString();
        const QStringList cells{spelled, name, QString::number(value)};
        for (int column = 0; column < cells.size(); ++column) {
            auto* item = new QTableWidgetItem(cells[column]);
            item->setData(kAddressRole, spelled);
            m_table->setItem(row, column, item);
        }
        ++row;
    }
    m_release->setEnabled(!m_table->selectedItems().isEmpty());
    m_releaseAll->setEnabled(!forces.empty());
}

void ForcesView::releaseSelected() {
    std::vector<lang::Address> chosen;
    for (const QModelIndex& index : m_table->selectionModel()->selectedRows())
        chosen.push_back(
            lang::readAddressWord(index.data(kAddressRole).toString().toStdString()).address);
    for (const lang::Address& address : chosen)
        m_session->release(address);
}

} // namespace rs::ui
