// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/VariableTableModel.h"

#include "document/ProjectDocument.h"
#include "pages/InstanceVariableText.h"
#include "shell/StatusColors.h"
#include "sim/Simulation.h"

#include <QApplication>
#include <QFont>
#include <QIcon>
#include <QPalette>

namespace rs::ui {

namespace {

QString fromView(std::string_view text) {
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

} // namespace

QString VariableTableModel::groupName(project::VariableGroup group) {
    using project::VariableGroup;
    switch (group) {
    case VariableGroup::SafetyInputs:
        return tr("Safety Inputs");
    case VariableGroup::SafetyOutputs:
        return tr("Safety Outputs");
    case VariableGroup::NonSafetyOutputs:
        return tr("NonSafety Outputs");
    case VariableGroup::GlobalMemories:
        return tr("Global Memories");
    case VariableGroup::Memories:
        return tr("Memories");
    case VariableGroup::Registers:
        return tr("Registers");
    case VariableGroup::DoubleRegisters:
        return tr("Double Registers");
    case VariableGroup::SystemMemories:
        return tr("System Memories");
    case VariableGroup::SystemRegisters:
        return tr("System Registers");
    case VariableGroup::AsiSlaves:
        return tr("AS-i Slaves");
    }
    return {};
}

VariableTableModel::VariableTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void VariableTableModel::show(ProjectDocument* document, int station,
                              project::VariableGroup group) {
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    m_station = station;
    m_group = group;
    if (document)
        connect(document, &ProjectDocument::changed, this, &VariableTableModel::reload);
    reload();
}

void VariableTableModel::reload() {
    std::vector<project::Variable> rows;
    m_instanceUses.clear();
    if (m_document) {
        rows = project::variableTable(m_document->project(), m_station, m_group);
        m_instanceUses =
            instanceUseTexts(blocks::instanceVariables(m_document->project(), m_station));
    }
    // Same rows (the usual case after an edit): only the cells change, so the
    // view keeps its selection, scroll position and open editor.
    if (rows.size() == m_rows.size() &&
        std::equal(rows.begin(), rows.end(), m_rows.begin(),
                   [](const auto& a, const auto& b) { return a.address == b.address; })) {
        m_rows = std::move(rows);
        if (!m_rows.empty())
            emit dataChanged(index(0, 0), index(rowCount() - 1, columnCount() - 1));
        return;
    }
    beginResetModel();
    m_rows = std::move(rows);
    endResetModel();
}

const project::Variable* VariableTableModel::variableAt(int row) const {
    if (row < 0 || row >= rowCount())
        return nullptr;
    return &m_rows[static_cast<std::size_t>(row)];
}

int VariableTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int VariableTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : DescriptionColumn + 1;
}

QVariant VariableTableModel::data(const QModelIndex& index, int role) const {
    const project::Variable* variable = variableAt(index.row());
    if (!variable)
        return {};
    if (role == kAddressRole)
        return QString::fromStdString(lang::toString(variable->address));
    const QPalette palette = QApplication::palette();
    switch (index.column()) {
    case StatusColumn:
        if (m_simulation)
            return liveStatus(*variable, role);
        // Outside simulation the column says where a variable is used, in
        // words and in the text's colour: a green dot would pass for a live value.
        if (role == Qt::DisplayRole || role == Qt::ToolTipRole) {
            QStringList uses;
            if (variable->used)
                uses << tr("Used in the code of the unit");
            if (auto found = m_instanceUses.find(variable->address); found != m_instanceUses.end())
                uses << found->second;
            if (uses.isEmpty())
                return {};
            if (role == Qt::DisplayRole)
                return tr("used", "a variable the code reads or writes");
            return uses.join(QLatin1Char('\n'));
        }
        if (role == Qt::ForegroundRole)
            return palette.color(QPalette::Disabled, QPalette::Text);
        if (role == Qt::TextAlignmentRole)
            return QVariant(Qt::AlignCenter);
        return {};
    case VariableColumn:
        if (role == Qt::DisplayRole)
            return QString::fromStdString(lang::toString(variable->address));
        return {};
    case AttributesColumn:
        if (role == Qt::DisplayRole) {
            QString marks;
            if (variable->global)
                marks += QStringLiteral("[G]");
            if (variable->exported)
                marks += QStringLiteral("[E]");
            if (variable->remanent)
                marks += QStringLiteral("[R]");
            return marks;
        }
        if (role == Qt::ForegroundRole && variable->remanent)
            return errorTextColor(palette);
        if (role == Qt::ToolTipRole) {
            QStringList lines;
            if (variable->global)
                lines << tr("[G] Global variable: visible to the other Plutos on the bus.");
            if (variable->exported)
                lines << tr("[E] Exported variable: made visible to the other Plutos on the bus.");
            if (variable->remanent)
                lines << tr("[R] Remanent variable: keeps its value when the power is off.");
            return lines.join(QLatin1Char('\n'));
        }
        return {};
    case NameColumn:
        if (role == Qt::EditRole)
            return QString::fromStdString(variable->name);
        if (role == Qt::DisplayRole)
            return variable->name.empty() ? fromView(variable->systemName)
                                          : QString::fromStdString(variable->name);
        if (variable->name.empty() && !variable->systemName.empty()) {
            if (role == Qt::ForegroundRole)
                return palette.color(QPalette::PlaceholderText);
            if (role == Qt::ToolTipRole)
                return tr("The manuals' name of this system variable");
        }
        return {};
    case DescriptionColumn:
        if (role == Qt::EditRole)
            return QString::fromStdString(variable->description);
        if (role == Qt::DisplayRole || role == Qt::ToolTipRole) {
            if (!variable->description.empty())
                return QString::fromStdString(variable->description);
            if (!variable->systemFunction.empty())
                return fromView(variable->systemFunction);
            const auto found = m_instanceUses.find(variable->address);
            if (found == m_instanceUses.end())
                return QString();
            QString uses = found->second;
            return role == Qt::DisplayRole ? uses.replace(QLatin1Char('\n'), QStringLiteral("; "))
                                           : uses;
        }
        if (role == Qt::ForegroundRole && variable->description.empty())
            return palette.color(QPalette::PlaceholderText);
        return {};
    default:
        return {};
    }
}

void VariableTableModel::setSimulation(const sim::Simulation* simulation) {
    if (simulation == m_simulation)
        return;
    m_simulation = simulation;
    refreshStatus();
}

void VariableTableModel::refreshStatus() {
    if (!m_rows.empty())
        emit dataChanged(index(0, StatusColumn), index(rowCount() - 1, StatusColumn));
}

QVariant VariableTableModel::liveStatus(const project::Variable& variable, int role) const {
    const std::int64_t value = m_simulation->value(variable.address);
    const sim::UnitEngine* unit = m_simulation->unit(variable.address.unit);
    const bool isForced = unit && unit->forces().count(variable.address) != 0;
    switch (role) {
    case Qt::DisplayRole:
        return isForced ? tr("%1 F", "a forced value").arg(value) : QString::number(value);
    case Qt::TextAlignmentRole:
        return QVariant(Qt::AlignCenter);
    case Qt::ForegroundRole:
        return isForced ? QVariant(errorTextColor(QApplication::palette())) : QVariant();
    case Qt::FontRole:
        if (isForced) {
            QFont bold;
            bold.setBold(true);
            return bold;
        }
        return {};
    case Qt::BackgroundRole:
        // A bit that is on, in the green of a powered ladder line, faint enough for the text.
        return variable.address.isBit() && value != 0 ? QVariant(QColor(0, 176, 0, 70))
                                                      : QVariant();
    case Qt::ToolTipRole:
        return isForced
                   ? tr("Forced to %1 in the simulation; release it in the Forces list.").arg(value)
                   : tr("The value after the last scan of the simulation");
    default:
        return {};
    }
}

QVariant VariableTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case StatusColumn:
        return tr("Status");
    case VariableColumn:
        return tr("Variable");
    case AttributesColumn:
        return tr("Attributes");
    case NameColumn:
        return tr("Symbolic Name");
    case DescriptionColumn:
        return tr("Description");
    default:
        return {};
    }
}

Qt::ItemFlags VariableTableModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags flags = QAbstractTableModel::flags(index);
    if (index.column() == NameColumn || index.column() == DescriptionColumn)
        flags |= Qt::ItemIsEditable;
    return flags;
}

bool VariableTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    const project::Variable* variable = variableAt(index.row());
    if (role != Qt::EditRole || !variable || !m_document)
        return false;
    const lang::Address address = variable->address;
    const QString where = QString::fromStdString(lang::toString(address));
    const std::string text = value.toString().trimmed().toStdString();
    if (index.column() == NameColumn) {
        if (text == variable->name)
            return false;
        if (auto problem = project::checkVariableName(m_document->project(), address, text)) {
            emit refused(QString::fromStdString(*problem));
            return false;
        }
        return m_document->edit(
            text.empty() ? tr("Remove Name of %1").arg(where)
                         : tr("Name %1 %2").arg(where, QString::fromStdString(text)),
            [&](project::Project& p) { project::setVariableName(p, address, text); });
    }
    if (index.column() == DescriptionColumn) {
        const std::string description = value.toString().toStdString();
        return m_document->edit(tr("Describe %1").arg(where), [&](project::Project& p) {
            project::setVariableDescription(p, address, description);
        });
    }
    return false;
}

} // namespace rs::ui
