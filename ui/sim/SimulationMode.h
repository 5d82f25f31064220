// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "SimulationSession.h"
// Qt 6.4's moc cannot parse the C++20 standard headers that the core brings in.
#ifndef Q_MOC_RUN
#include "LiveLadder.h"
#endif

#include <QObject>
#include <QPointer>

#include <optional>
#include <vector>

class QAction;
class QDockWidget;
class QLabel;
class QProgressBar;
class QPushButton;

namespace rs::ui {

class BusStatusView;
class ForcesView;
class GatewayView;
class ModbusService;
class LadderPage;
class MainWindow;
class ProjectDocument;
class ScenarioFileViewer;
class ScenarioResultsView;
class SimulationControls;
class WatchView;
class WaveformPanel;

// The window in simulation mode (the original's "online"): the Simulate menu
// and tool bar, the Forces, Watch, Waveform, Bus Status and Scenarios docks,
// the unit's code in the status bar, and the live state on the pages shown:
// the ladder page draws the last scan's power and takes clicks to toggle
// inputs and a menu to force, the variables page's Status column shows the
// values. The ladder page is read-only while live; any change of the
// project ends the simulation.
class SimulationMode : public QObject {
    Q_OBJECT
public:
    explicit SimulationMode(MainWindow* window);
    ~SimulationMode() override;

    SimulationSession* session() { return &m_session; }
    SimulationControls* controls() const { return m_controls; }
    ForcesView* forcesView() const { return m_forces; }
    WatchView* watchView() const { return m_watch; }
    BusStatusView* busStatusView() const { return m_bus; }
    GatewayView* gatewayView() const { return m_gateway; }
    ModbusService* modbusService() const { return m_modbus; }
    QAction* serveModbusAction() const { return m_serveModbus; }
    WaveformPanel* waveformPanel() const { return m_waveform; }
    ScenarioResultsView* scenarioResults() const { return m_scenarios; }
    ScenarioFileViewer* scenarioViewer() const { return m_viewer; }
    QLabel* unitCode() const { return m_unitCode; }
    const LadderLiveState& liveState() const { return m_live; }

    // Starts simulating the window's current project; the reason when it cannot.
    QString begin();
    void end();
    // Starts a scenario file on the current project; the status bar shows its
    // progress and a Cancel button, and the Scenarios dock lists its result.
    void startScenario(const QString& path);
    // The same, waiting for the result (the command line, tests).
    SimulationSession::ScenarioResult runScenario(const QString& path);
    QProgressBar* scenarioProgress() const { return m_scenarioProgress; }
    QPushButton* cancelScenarioButton() const { return m_cancelScenario; }

    // What a click on an element's operand does: an input toggles.
    void operandClicked(const QString& address);
    // Force 0 / Force 1 / Force Value... / Release for the operand.
    void showOperandMenu(const QString& address, const QPoint& globalPosition);
    // Shows the live state on the page the window shows now.
    void refresh();

private:
    // A dock at the bottom, a tab beside Problems and Output or (the waveform) on its own.
    QDockWidget* addDock(QWidget* content, const QString& title, const char* name,
                         bool withProblems = true);
    void stateChanged();
    void scenarioFinished(const SimulationSession::ScenarioResult& result);
    // The docks of a running simulation, and the status bar's word that it runs.
    void showSimulationDocks(const ProjectDocument* document);
    // Back to editing: the simulation's docks go, remembered for the next time.
    void hideSimulationDocks();
    void showBottomDocks();
    void message(const QString& text);
    // Simulate > Serve Modbus TCP: on, at the preferences' address; off.
    void serveModbus(bool on);

    MainWindow* m_window;
    SimulationSession m_session;
    SimulationControls* m_controls;
    ForcesView* m_forces;
    WatchView* m_watch;
    BusStatusView* m_bus;
    ModbusService* m_modbus;
    QAction* m_serveModbus;
    GatewayView* m_gateway;
    WaveformPanel* m_waveform;
    ScenarioResultsView* m_scenarios;
    ScenarioFileViewer* m_viewer;
    QLabel* m_unitCode;
    QProgressBar* m_scenarioProgress;
    QPushButton* m_cancelScenario;
    QDockWidget* m_forcesDock = nullptr;
    QDockWidget* m_watchDock = nullptr;
    QDockWidget* m_busDock = nullptr;
    QDockWidget* m_gatewayDock = nullptr;
    QDockWidget* m_waveformDock = nullptr;
    QDockWidget* m_scenariosDock = nullptr;
    bool m_simulationDocksShown = false;
    // Which simulation docks the user had open when the last simulation ended.
    std::optional<std::vector<QDockWidget*>> m_lastSimulationDocks;
    LadderLiveState m_live;
    LiveLadderBuilder m_builder;
    QPointer<LadderPage> m_liveLadder; // the page showing m_live, if any
};

} // namespace rs::ui
