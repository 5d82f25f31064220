// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStringList>
#include <QWidget>

class QAction;
class QLabel;
class QTreeWidget;

namespace rs::ui {

class ModbusService;
class SimulationSession;

// The Gateway dock while simulating: each gateway of the project with what it
// holds as the simulation runs — Node Status, each Pluto's 32 bits of global
// data, the additional data areas in use, Data to Pluto as the fieldbus last
// wrote it — and whether Modbus TCP is served, with the clients connected.
class GatewayView : public QWidget {
    Q_OBJECT
public:
    enum Column { DataColumn, HexColumn, BitsColumn };

    GatewayView(SimulationSession* session, ModbusService* service, QAction* serve,
                QWidget* parent = nullptr);

    QTreeWidget* tree() const { return m_tree; }
    QLabel* serving() const { return m_serving; }
    void refresh();

private:
    void showService();

    SimulationSession* m_session;
    ModbusService* m_service;
    QLabel* m_serving;
    QTreeWidget* m_tree;
    QStringList m_shape; // the rows shown, to update their values in place
};

} // namespace rs::ui
