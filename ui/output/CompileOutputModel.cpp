// SPDX-License-Identifier: GPL-3.0-or-later
#include "output/CompileOutputModel.h"

#include <QFont>

namespace rs::ui {

namespace {

QString placeText(const project::TextPlace& place, int column) {
    using Kind = project::TextPlace::Kind;
    switch (place.kind) {
    case Kind::UnitCode:
        return CompileOutputModel::tr("Pluto %1, line %2:%3")
            .arg(place.station)
            .arg(place.line)
            .arg(column);
    case Kind::Unit:
        return CompileOutputModel::tr("Pluto %1, settings").arg(place.station);
    case Kind::Variable:
        return CompileOutputModel::tr("Pluto %1, %2")
            .arg(place.station)
            .arg(QString::fromStdString(lang::toString(place.address)));
    case Kind::Project:
        break;
    }
    return CompileOutputModel::tr("Project");
}

} // namespace

CompileOutputModel::CompileOutputModel(QObject* parent)
    : QAbstractTableModel(parent), m_errorIcon(QStringLiteral(":/icons/error.svg")),
      m_warningIcon(QStringLiteral(":/icons/warning.svg")) {}

void CompileOutputModel::setRows(std::vector<Row> rows) {
    beginResetModel();
    m_rows = std::move(rows);
    endResetModel();
}

int CompileOutputModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int CompileOutputModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : 2;
}

QVariant CompileOutputModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const Row& r = row(index.row());
    const bool finding = r.finding;
    const bool error = r.severity == lang::Severity::Error;
    switch (role) {
    case Qt::DisplayRole:
        if (index.column() == PlaceColumn)
            return finding ? placeText(r.place, r.column) : QString();
        if (!finding)
            return r.text;
        return (error ? tr("error: %1") : tr("warning: %1")).arg(QString::fromStdString(r.message));
    case Qt::DecorationRole:
        if (index.column() == PlaceColumn && r.severity)
            return error ? m_errorIcon : m_warningIcon;
        return {};
    case Qt::ToolTipRole:
        if (!finding)
            return r.toolTip.isEmpty() ? QVariant() : QVariant(r.toolTip);
        if (index.column() == PlaceColumn)
            return tr("Line %1 of the project file").arg(r.fileLine);
        return QString::fromStdString(r.message);
    case Qt::FontRole:
        if (r.bold) {
            QFont bold;
            bold.setBold(true);
            return bold;
        }
        return {};
    default:
        return {};
    }
}

QVariant CompileOutputModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    return section == PlaceColumn ? tr("Place") : tr("Message");
}

} // namespace rs::ui
