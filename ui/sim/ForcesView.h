// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QPushButton;
class QTableWidget;

namespace rs::ui {

class SimulationSession;

// Every force of the simulation in one list (the Forces dock): variable,
// symbolic name and forced value; released from here one by one or all at once.
class ForcesView : public QWidget {
    Q_OBJECT
public:
    explicit ForcesView(SimulationSession* session, QWidget* parent = nullptr);

    QTableWidget* table() const { return m_table; }
    void refresh();

private:
    void releaseSelected();

    SimulationSession* m_session;
    QTableWidget* m_table;
    QPushButton* m_release;
    QPushButton* m_releaseAll;
};

} // namespace rs::ui
