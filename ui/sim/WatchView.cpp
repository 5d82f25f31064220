// SPDX-License-Identifier: GPL-3.0-or-later
#include "WatchView.h"

#include "SimulationSession.h"
#include "document/ProjectDocument.h"
#include "project/VariableTable.h"
#include "shell/CompleterKeys.h"
#include "shell/StatusColors.h"

#include <QCompleter>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QStringListModel>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace rs::ui {

WatchView::WatchView(SimulationSession* session, QWidget* parent)
    : QWidget(parent), m_session(session), m_input(new QLineEdit(this)),
      m_completer(new QCompleter(this)), m_message(new QLabel(this)),
      m_table(new QTableWidget(0, 3, this)) {
    m_input->setObjectName(QStringLiteral("watchInput"));
    m_input->setPlaceholderText(tr("Symbolic name or address, e.g. Q0.2"));
    m_completer->setCaseSensitivity(Qt::CaseInsensitive);
    m_completer->setFilterMode(Qt::MatchContains);
    m_completer->setModel(new QStringListModel(m_completer));
    m_input->setCompleter(m_completer);
    finishCompletionInOneKey(m_completer);
    auto* addButton = new QPushButton(tr("&Watch"), this);
    m_message->setObjectName(QStringLiteral("watchMessage"));
    markAsError(m_message);
    m_message->hide();

    m_table->setObjectName(QStringLiteral("watchTable"));
    m_table->setHorizontalHeaderLabels({tr("Variable"), tr("Symbolic Name"), tr("Value")});
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setContextMenuPolicy(Qt::CustomContextMenu);
    m_table->verticalHeader()->hide();
    // Variable and name as wide as their heading or longest entry, in any language.
    for (const int column : {VariableColumn, NameColumn})
        m_table->horizontalHeader()->setSectionResizeMode(column, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setToolTip(tr("Type a value to set an input or force any other variable"));

    auto* top = new QHBoxLayout;
    top->addWidget(m_input, 1);
    top->addWidget(addButton);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(top);
    layout->addWidget(m_message);
    layout->addWidget(m_table);

    auto addTyped = [this] {
        const QString error = add(m_input->text());
        m_message->setText(error);
        m_message->setVisible(!error.isEmpty());
        if (error.isEmpty())
            m_input->clear();
    };
    connect(m_input, &QLineEdit::returnPressed, this, addTyped);
    connect(addButton, &QPushButton::clicked, this, addTyped);
    connect(m_table, &QTableWidget::itemChanged, this, &WatchView::valueEdited);
    connect(m_table, &QWidget::customContextMenuRequested, this, &WatchView::showMenu);
    connect(m_session, &SimulationSession::updated, this, &WatchView::refresh);
    connect(m_session, &SimulationSession::projectChanged, this, [this] {
        m_variables.clear();
        rebuild();
    });
    connect(m_session, &SimulationSession::stateChanged, this, [this] {
        static_cast<QStringListModel*>(m_completer->model())
            ->setStringList(m_session->operandWords());
        rebuild();
    });
}

QString WatchView::add(const QString& word) {
    if (word.trimmed().isEmpty())
        return tr("Type a symbolic name or an address.");
    Entry entry;
    QString error;
    if (!m_session->resolveChannel(word, entry.address, entry.channel, error))
        return error;
    if (std::find(m_variables.begin(), m_variables.end(), entry) == m_variables.end())
        m_variables.push_back(entry);
    rebuild();
    return {};
}

void WatchView::remove(const Entry& entry) {
    std::erase(m_variables, entry);
    rebuild();
}

void WatchView::rebuild() {
    m_refreshing = true;
    m_table->setRowCount(static_cast<int>(m_variables.size()));
    const ProjectDocument* document = m_session->document();
    for (int row = 0; row < static_cast<int>(m_variables.size()); ++row) {
        const Entry& entry = m_variables[static_cast<std::size_t>(row)];
        const QString channel =
            entry.channel ? QStringLiteral(".ch%1").arg(entry.channel) : QString();
        auto* variable =
            new QTableWidgetItem(QString::fromStdString(lang::toString(entry.address)) + channel);
        const QString declared =
            document
                ? QString::fromStdString(project::variableName(document->project(), entry.address))
                : QString();
        auto* name = new QTableWidgetItem(declared.isEmpty() ? declared : declared + channel);
        for (QTableWidgetItem* item : {variable, name})
            item->setFlags(item->flags() & ~Qt::ItemIsEditable);
        m_table->setItem(row, VariableColumn, variable);
        m_table->setItem(row, NameColumn, name);
        m_table->setItem(row, ValueColumn, new QTableWidgetItem);
    }
    m_refreshing = false;
    refresh();
}

void WatchView::refresh() {
    const sim::Simulation* simulation = m_session->simulation();
    m_refreshing = true;
    for (int row = 0; row < m_table->rowCount(); ++row) {
        QTableWidgetItem* item = m_table->item(row, ValueColumn);
        const Entry& entry = m_variables[static_cast<std::size_t>(row)];
        const lang::Address& address = entry.address;
        if (!simulation) {
            item->setText({});
            item->setFlags(item->flags() & ~Qt::ItemIsEditable);
            continue;
        }
        item->setFlags(item->flags() | Qt::ItemIsEditable);
        const bool forced = !entry.channel && m_session->isForced(address);
        const QString value =
            QString::number(entry.channel ? simulation->channel(address, entry.channel)
                                          : simulation->value(address));
        item->setText(forced ? tr("%1 F", "a forced value").arg(value) : value);
        item->setForeground(forced ? errorTextColor(palette()) : palette().color(QPalette::Text));
        item->setToolTip(forced ? tr("Forced") : QString());
    }
    m_refreshing = false;
}

void WatchView::valueEdited(QTableWidgetItem* item) {
    if (m_refreshing || item->column() != ValueColumn || !m_session->isActive())
        return;
    bool ok = false;
    const qlonglong value = item->text().section(QLatin1Char(' '), 0, 0).toLongLong(&ok);
    const Entry entry = m_variables[static_cast<std::size_t>(item->row())];
    if (!ok || (entry.channel && value != 0 && value != 1)) {
        m_message->setText(ok ? tr("A channel is open (0) or closed (1).")
                              : tr("“%1” is not a number.").arg(item->text()));
        m_message->show();
        refresh();
        return;
    }
    m_message->hide();
    if (entry.channel)
        m_session->setChannel(entry.address, entry.channel, value != 0);
    else
        m_session->set(entry.address, value);
}

void WatchView::showMenu(const QPoint& at) {
    const int row = m_table->rowAt(at.y());
    if (row < 0)
        return;
    const Entry entry = m_variables[static_cast<std::size_t>(row)];
    QMenu menu(this);
    QAction* release = menu.addAction(tr("&Release Force"));
    release->setEnabled(!entry.channel && m_session->isForced(entry.address));
    connect(release, &QAction::triggered, this,
            [this, entry] { m_session->release(entry.address); });
    connect(menu.addAction(tr("Stop &Watching")), &QAction::triggered, this,
            [this, entry] { remove(entry); });
    menu.exec(m_table->viewport()->mapToGlobal(at));
}

} // namespace rs::ui
