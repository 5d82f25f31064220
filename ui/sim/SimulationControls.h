// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>

class QAction;
class QComboBox;
class QLabel;
class QMenu;
class QToolBar;
class QWidget;

namespace rs::ui {

class SimulationSession;

// The Simulate menu and tool bar: simulation on and off (the original's
// "Online"), start and stop of the program, single scan, reset, the speed
// and the virtual clock, and running a scenario file.
class SimulationControls : public QObject {
    Q_OBJECT
public:
    SimulationControls(SimulationSession* session, QWidget* window);

    QMenu* menu() const { return m_menu; }
    QToolBar* toolBar() const { return m_toolBar; }
    QAction* simulateAction() const { return m_simulate; }
    QAction* startAction() const { return m_start; }
    QAction* stopAction() const { return m_stop; }
    QAction* singleScanAction() const { return m_singleScan; }
    QAction* resetAction() const { return m_reset; }
    QAction* runScenarioAction() const { return m_runScenario; }
    QComboBox* speed() const { return m_speed; }
    QLabel* clock() const { return m_clock; }

    // Whether there is a project to simulate.
    void setProjectAvailable(bool available);
    void showClock();

signals:
    // The window starts or ends the simulation: it knows the project.
    void simulateToggled(bool on);
    void scenarioRequested();

private:
    void updateActions();

    SimulationSession* m_session;
    QMenu* m_menu;
    QToolBar* m_toolBar;
    QAction* m_simulate;
    QAction* m_start;
    QAction* m_stop;
    QAction* m_singleScan;
    QAction* m_reset;
    QAction* m_runScenario;
    QComboBox* m_speed;
    QLabel* m_clock;
    bool m_projectAvailable = false;
};

} // namespace rs::ui
