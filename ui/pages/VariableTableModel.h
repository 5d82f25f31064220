// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Holds core types by value, so their headers come in here; Qt 6.4's moc cannot
// parse the C++20 standard headers they bring in (<concepts>) and needs only the names.
#ifndef Q_MOC_RUN
#include "project/VariableTable.h"
#endif

#include <QAbstractTableModel>
#include <QPointer>

#include <map>
#include <vector>

namespace rs::sim {
class Simulation;
}

namespace rs::ui {

class ProjectDocument;

// One tab of the Variables page: the variables of one kind of one unit, with
// Status, Variable, attributes ([G] global, [E] exported, [R] remanent),
// Symbolic Name and Description. Names and descriptions are edited in place;
// each edit is one undo step of the project, and a name the manual's rules
// or another variable forbid is refused with the reason. A variable that a
// block instance binds or was given counts as used, and says by which block
// where it has no description of its own.
class VariableTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { StatusColumn, VariableColumn, AttributesColumn, NameColumn, DescriptionColumn };
    // The variable's address as text ("M0.12") under this role, for any column.
    static constexpr int kAddressRole = Qt::UserRole;

    explicit VariableTableModel(QObject* parent = nullptr);

    void show(ProjectDocument* document, int station, project::VariableGroup group);
    ProjectDocument* document() const { return m_document; }
    const project::Variable* variableAt(int row) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

    static QString groupName(project::VariableGroup group);

    // While a simulation runs, the Status column shows every variable's value
    // and marks the forced ones; without one, it marks the variables in use.
    void setSimulation(const sim::Simulation* simulation);
    // The simulation scanned: the Status column shows the new values.
    void refreshStatus();

    // Simulating: the Status column shows live values.
    bool isLive() const { return m_simulation != nullptr; }

signals:
    // An edit was refused; the message says why.
    void refused(const QString& message);

private:
    void reload();
    QVariant liveStatus(const project::Variable& variable, int role) const;

    QPointer<ProjectDocument> m_document;
    int m_station = 0;
    project::VariableGroup m_group = project::VariableGroup::SafetyInputs;
    std::vector<project::Variable> m_rows;
    std::map<lang::Address, QString> m_instanceUses; // what the unit's block instances use
    const sim::Simulation* m_simulation = nullptr;
};

} // namespace rs::ui
