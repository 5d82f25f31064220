// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringList>
#include <QWidget>

#include <cstdint>
#include <map>

class QTableWidget;

namespace rs::ui {

class SimulationSession;

// Pluto's error code as the manual's tool bar shows it, "E0=No Error"; from
// SR_ErrorCode, which only a force changes in the simulator.
QString unitCodeText(int station, int code);

// The Bus Status dock (manual Part 1, 15.6): every unit of the project with
// its state in the simulation and its error code.
class BusStatusView : public QWidget {
    Q_OBJECT
public:
    // The signature is of the image simulated (docs/review.md), what
    // `rungsmith-cli signature` prints for the project as compiled.
    enum Column { StationColumn, UnitColumn, StateColumn, CodeColumn, SignatureColumn };

    explicit BusStatusView(SimulationSession* session, QWidget* parent = nullptr);

    QTableWidget* table() const { return m_table; }
    void refresh();

private:
    // One row's cells; `failing` shows its state and code as an error.
    void setRow(int row, const QStringList& cells, bool failing);

    SimulationSession* m_session;
    QTableWidget* m_table;
    // Each unit's signature, of the images whose project signature this is:
    // reading them means serialising every image, too much for every update.
    std::map<int, QString> m_signatures;
    std::uint32_t m_signedProject = 0;
};

} // namespace rs::ui
