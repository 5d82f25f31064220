// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/VariablesPage.h"

#include "document/ProjectDocument.h"
#include "pages/SymbolicNameDelegate.h"
#include "pages/VariableTableModel.h"
#include "project/ExportedVariables.h"
#include "project/UnitSettings.h"
#include "shell/PageTitle.h"
#include "shell/StatusColors.h"
#include "shell/UnitCaption.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QSortFilterProxyModel>
#include <QTabBar>
#include <QTableView>
#include <QVBoxLayout>

namespace rs::ui {

namespace {

// How a cell is edited while not simulating.
constexpr QAbstractItemView::EditTriggers kEditTriggers = QAbstractItemView::DoubleClicked |
                                                          QAbstractItemView::EditKeyPressed |
                                                          QAbstractItemView::AnyKeyPressed;

} // namespace

VariablesPage::VariablesPage(QWidget* parent)
    : QWidget(parent), m_title(new PageTitle(this)), m_tabs(new QTabBar(this)),
      m_filter(new QLineEdit(this)), m_table(new QTableView(this)), m_message(new QLabel(this)),
      m_exports(new QLabel(this)), m_model(new VariableTableModel(this)),
      m_proxy(new QSortFilterProxyModel(this)) {
    m_tabs->setObjectName(QStringLiteral("variableTabs"));
    m_tabs->setExpanding(false);
    m_tabs->setDocumentMode(true);
    m_tabs->setUsesScrollButtons(true);
    m_filter->setObjectName(QStringLiteral("variableFilter"));
    m_filter->setPlaceholderText(tr("Filter by variable, name or description"));
    m_filter->setClearButtonEnabled(true);
    m_filter->setMinimumWidth(260);
    m_table->setObjectName(QStringLiteral("variableTable"));
    m_message->setObjectName(QStringLiteral("variableMessage"));
    m_message->setWordWrap(true);
    markAsError(m_message);
    m_message->hide();
    m_exports->setObjectName(QStringLiteral("variableExportPairs"));

    m_proxy->setSourceModel(m_model);
    m_proxy->setFilterKeyColumn(-1);
    m_proxy->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_table->setModel(m_proxy);
    auto* delegate = new SymbolicNameDelegate(this);
    m_table->setItemDelegateForColumn(VariableTableModel::NameColumn, delegate);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(kEditTriggers);
    m_table->setAlternatingRowColors(true);
    m_table->setContextMenuPolicy(Qt::CustomContextMenu);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 8);
    QHeaderView* header = m_table->horizontalHeader();
    header->setSectionResizeMode(VariableTableModel::StatusColumn, QHeaderView::Fixed);
    header->resizeSection(VariableTableModel::StatusColumn, 56);
    header->resizeSection(VariableTableModel::VariableColumn, 110);
    header->resizeSection(VariableTableModel::AttributesColumn, 96);
    header->resizeSection(VariableTableModel::NameColumn, 220);
    header->setStretchLastSection(true);

    auto* legend = new QLabel(tr("Variable attributes: [G] global, visible to the other Plutos on "
                                 "the bus; [E] exported; [R] remanent, kept at power off."),
                              this);
    legend->setWordWrap(true);
    legend->setForegroundRole(QPalette::PlaceholderText);

    auto* remanent = new QPushButton(tr("&Remanent Variables..."), this);
    auto* importCsv = new QPushButton(tr("&Import CSV..."), this);
    auto* exportCsv = new QPushButton(tr("E&xport CSV..."), this);
    remanent->setObjectName(QStringLiteral("remanentButton"));

    auto* top = new QHBoxLayout;
    top->addWidget(legend, 1);
    top->addWidget(m_filter);
    auto* bottom = new QHBoxLayout;
    bottom->addWidget(m_exports, 1);
    bottom->addWidget(remanent);
    bottom->addWidget(importCsv);
    bottom->addWidget(exportCsv);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addLayout(top);
    layout->addWidget(m_tabs);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_message);
    layout->addLayout(bottom);

    connect(m_tabs, &QTabBar::currentChanged, this, [this](int tab) {
        if (!m_fillingTabs)
            showGroup(tab);
    });
    connect(m_filter, &QLineEdit::textChanged, m_proxy,
            &QSortFilterProxyModel::setFilterFixedString);
    connect(m_model, &VariableTableModel::refused, this, &VariablesPage::showMessage);
    connect(delegate, &SymbolicNameDelegate::problemChanged, this, &VariablesPage::showMessage);
    connect(m_table, &QWidget::customContextMenuRequested, this, &VariablesPage::showContextMenu);
    connect(m_table, &QAbstractItemView::doubleClicked, this, [this](const QModelIndex& index) {
        if (m_model->isLive())
            emit operandToggled(addressAt(index));
    });
    m_table->installEventFilter(this);
    connect(remanent, &QPushButton::clicked, this,
            [this] { emit remanentRequested(m_document, m_station); });
    connect(importCsv, &QPushButton::clicked, this,
            [this] { emit csvImportRequested(m_document, m_station); });
    connect(exportCsv, &QPushButton::clicked, this,
            [this] { emit csvExportRequested(m_document, m_station); });
    m_remanentButton = remanent;
}

void VariablesPage::showUnit(ProjectDocument* document, int station) {
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    m_station = station;
    m_groups.clear();
    if (document) {
        connect(document, &ProjectDocument::changed, this, &VariablesPage::refresh);
        connect(document, &ProjectDocument::permissionChanged, this,
                &VariablesPage::updateEditTriggers);
    }
    updateEditTriggers();
    refresh();
}

void VariablesPage::updateEditTriggers() {
    // While simulating, a double click or a key acts on the simulation, not
    // on the project (an edit would end the simulation); a project open
    // without full permission takes no names or descriptions.
    const bool editable =
        !m_simulating && m_document && m_document->permission() == project::Permission::Full;
    m_table->setEditTriggers(editable ? kEditTriggers : QAbstractItemView::NoEditTriggers);
}

void VariablesPage::refresh() {
    if (!m_document)
        return;
    const project::Project& p = m_document->project();
    const auto unit = project::unitSettings(p, m_station);
    if (!unit)
        return;
    m_title->setTitle(tr("%1 — Variables").arg(unitCaption(*unit)));
    const target::UnitTypeInfo& type = target::unitTypeInfo(unit->type);
    const auto groups = project::variableGroups(type, unit->instructionSet);
    if (groups != m_groups) {
        const int current = m_tabs->currentIndex();
        const bool hadGroup = current >= 0 && current < static_cast<int>(m_groups.size());
        const project::VariableGroup previous =
            hadGroup ? m_groups[static_cast<std::size_t>(current)] : groups.front();
        m_groups = groups;
        m_fillingTabs = true;
        while (m_tabs->count())
            m_tabs->removeTab(0);
        for (auto group : m_groups)
            m_tabs->addTab(VariableTableModel::groupName(group));
        m_fillingTabs = false;
        // A hidden tab bar does not tell the layout that its height changed.
        m_tabs->updateGeometry();
        const auto found = std::find(m_groups.begin(), m_groups.end(), previous);
        const int tab = found == m_groups.end() ? 0 : static_cast<int>(found - m_groups.begin());
        m_tabs->setCurrentIndex(tab);
        showGroup(tab);
    }
    m_remanentButton->setEnabled(type.remanent);
    if (unit->instructionSet < 3)
        m_exports->setText(tr("Export variables need instruction set 3."));
    else
        m_exports->setText(tr("Export variables: %1 of %2 extra telegram pairs (project: %3 of %4)")
                               .arg(project::telegramPairs(p, m_station))
                               .arg(project::kTelegramPairsPerUnit)
                               .arg(project::telegramPairs(p))
                               .arg(project::kTelegramPairsPerProject));
}

void VariablesPage::showGroup(int tab) {
    if (tab < 0 || tab >= static_cast<int>(m_groups.size()))
        return;
    m_model->show(m_document, m_station, m_groups[static_cast<std::size_t>(tab)]);
}

void VariablesPage::setSimulation(const sim::Simulation* simulation) {
    m_model->setSimulation(simulation);
    m_simulating = simulation != nullptr;
    updateEditTriggers();
    // Room for a value and its force mark while simulating; the icon needs less.
    m_table->horizontalHeader()->resizeSection(VariableTableModel::StatusColumn,
                                               simulation ? 80 : 56);
}

void VariablesPage::refreshStatus() {
    m_model->refreshStatus();
}

bool VariablesPage::showVariable(const lang::Address& address) {
    if (!m_document)
        return false;
    const auto unit = project::unitSettings(m_document->project(), address.unit);
    if (!unit || address.unit != m_station)
        return false;
    const auto group =
        project::groupOf(target::unitTypeInfo(unit->type), unit->instructionSet, address);
    auto found = group ? std::find(m_groups.begin(), m_groups.end(), *group) : m_groups.end();
    if (found == m_groups.end())
        return false;
    m_filter->clear();
    m_tabs->setCurrentIndex(static_cast<int>(found - m_groups.begin()));
    for (int row = 0; row < m_model->rowCount(); ++row) {
        if (m_model->variableAt(row)->address == address) {
            const QModelIndex index =
                m_proxy->mapFromSource(m_model->index(row, VariableTableModel::NameColumn));
            m_table->setCurrentIndex(index);
            m_table->scrollTo(index, QAbstractItemView::PositionAtCenter);
            return true;
        }
    }
    return false;
}

QString VariablesPage::message() const {
    return m_message->isVisible() ? m_message->text() : QString();
}

void VariablesPage::showMessage(const QString& message) {
    m_message->setText(message);
    m_message->setVisible(!message.isEmpty());
}

QString VariablesPage::setExported(const lang::Address& address, bool exported) {
    if (!m_document)
        return {};
    QString refusal;
    m_document->edit(
        exported ? tr("Export %1").arg(QString::fromStdString(lang::toString(address)))
                 : tr("Stop Exporting %1").arg(QString::fromStdString(lang::toString(address))),
        [&](project::Project& p) {
            if (auto problem = project::setExported(p, address, exported))
                refusal = QString::fromStdString(*problem);
        });
    showMessage(refusal);
    return refusal;
}

QString VariablesPage::addressAt(const QModelIndex& proxyIndex) const {
    const project::Variable* variable = m_model->variableAt(m_proxy->mapToSource(proxyIndex).row());
    return variable ? QString::fromStdString(lang::toString(variable->address)) : QString();
}

bool VariablesPage::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_table && event->type() == QEvent::KeyPress && m_model->isLive() &&
        static_cast<QKeyEvent*>(event)->key() == Qt::Key_Space) {
        if (const QString address = addressAt(m_table->currentIndex()); !address.isEmpty())
            emit operandToggled(address);
        return true;
    }
    return QWidget::eventFilter(watched, event);
}

void VariablesPage::showContextMenu(const QPoint& at) {
    if (!m_document)
        return;
    if (m_model->isLive()) {
        if (const QString address = addressAt(m_table->indexAt(at)); !address.isEmpty())
            emit operandMenuRequested(address, m_table->viewport()->mapToGlobal(at));
        return;
    }
    const QModelIndex index = m_proxy->mapToSource(m_table->indexAt(at));
    const project::Variable* variable = m_model->variableAt(index.row());
    QMenu menu(this);
    if (variable) {
        const lang::Address address = variable->address;
        QAction* exportAction = menu.addAction(tr("&Export Variable [E]"));
        exportAction->setCheckable(true);
        exportAction->setChecked(variable->exported);
        const auto problem = project::checkExportable(m_document->project(), address);
        exportAction->setEnabled(variable->exported || !problem);
        if (problem)
            exportAction->setToolTip(QString::fromStdString(*problem));
        connect(exportAction, &QAction::toggled, this,
                [this, address](bool on) { setExported(address, on); });
        menu.addSeparator();
    }
    QAction* remanent = menu.addAction(tr("&Remanent Variables..."));
    remanent->setEnabled(m_remanentButton->isEnabled());
    connect(remanent, &QAction::triggered, this,
            [this] { emit remanentRequested(m_document, m_station); });
    menu.addSeparator();
    connect(menu.addAction(tr("&Import Variable Names from CSV...")), &QAction::triggered, this,
            [this] { emit csvImportRequested(m_document, m_station); });
    connect(menu.addAction(tr("E&xport Variable Names to CSV...")), &QAction::triggered, this,
            [this] { emit csvExportRequested(m_document, m_station); });
    menu.setToolTipsVisible(true);
    menu.exec(m_table->viewport()->mapToGlobal(at));
}

} // namespace rs::ui
