// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Holds core types by value, so their headers come in here; Qt 6.4's moc cannot
// parse the C++20 standard headers they bring in (<concepts>) and needs only the names.
#ifndef Q_MOC_RUN
#include "project/VariableTable.h"
#endif

#include <QPointer>
#include <QWidget>

#include <vector>

class QLabel;
class QLineEdit;
class QPushButton;
class QSortFilterProxyModel;
class QTabBar;
class QTableView;

namespace rs::sim {
class Simulation;
}

namespace rs::ui {

class PageTitle;
class ProjectDocument;
class VariableTableModel;

// The Variables page (manual Part 1, 3.9 and 10): one tab per kind of
// variable of the unit's type, a filter, names and descriptions edited in
// the table, export variables from the context menu within the telegram
// limits, and the way to the remanent variables and to CSV.
class VariablesPage : public QWidget {
    Q_OBJECT
public:
    explicit VariablesPage(QWidget* parent = nullptr);

    void showUnit(ProjectDocument* document, int station);
    // Shows the tab of the variable and selects its row.
    bool showVariable(const lang::Address& address);

    QTabBar* tabs() const { return m_tabs; }
    QTableView* table() const { return m_table; }
    VariableTableModel* model() const { return m_model; }
    QString message() const;

    // The Status column's live values (VariableTableModel::setSimulation).
    void setSimulation(const sim::Simulation* simulation);
    void refreshStatus();

    // Marks or unmarks the variable as exported; the reason when refused.
    QString setExported(const lang::Address& address, bool exported);

signals:
    void remanentRequested(ProjectDocument* document, int station);
    void csvImportRequested(ProjectDocument* document, int station);
    void csvExportRequested(ProjectDocument* document, int station);
    // While simulating: a double click or Space on a variable's row (an input
    // toggles), and its context menu (force, release, watch).
    void operandToggled(const QString& address);
    void operandMenuRequested(const QString& address, const QPoint& globalPosition);

private:
    void refresh();
    void updateEditTriggers();
    void showGroup(int tab);
    void showMessage(const QString& message);
    void showContextMenu(const QPoint& at);
    bool eventFilter(QObject* watched, QEvent* event) override;
    QString addressAt(const QModelIndex& proxyIndex) const;

    PageTitle* m_title;
    QTabBar* m_tabs;
    QLineEdit* m_filter;
    bool m_simulating = false;
    QTableView* m_table;
    QLabel* m_message;
    QLabel* m_exports;
    QPushButton* m_remanentButton = nullptr;
    VariableTableModel* m_model;
    QSortFilterProxyModel* m_proxy;
    std::vector<project::VariableGroup> m_groups;
    QPointer<ProjectDocument> m_document;
    int m_station = 0;
    bool m_fillingTabs = false;
};

} // namespace rs::ui
