// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Holds core types by value, so their headers come in here; Qt 6.4's moc cannot
// parse the C++20 standard headers they bring in (<concepts>) and needs only the names.
#ifndef Q_MOC_RUN
#include "compiler/Image.h"
#include "gateway/GatewayNode.h"
#include "sim/RealTimePacer.h"
#include "sim/ScenarioRunner.h"
#include "sim/Simulation.h"
#include "sim/WaveformRecorder.h"
#endif

#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QTimer>

#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace rs::ui {

class ProjectDocument;

// The project's units running in the simulator behind the window. It compiles
// the project, runs the scans on a timer paced to the wall clock (real time,
// faster, or as fast as the machine goes), and tells the views when to show
// the state: at the preference's screen update interval while running, and
// at once after a user's single scan, reset, set or force.
//
// The simulation is of the project as it was compiled: a change of the
// project ends it (the views go back to editing), and nothing here ever
// changes the project. Forces live in the simulation only.
class SimulationSession : public QObject {
    Q_OBJECT
public:
    enum class State { Off, Stopped, Running };
    // RealTimePacer's speed factors.
    static constexpr double kRealTime = 1.0;
    static constexpr double kTenTimes = 10.0;
    static constexpr double kAsFastAsPossible = 0.0;

    explicit SimulationSession(QObject* parent = nullptr);
    ~SimulationSession() override;

    // Compiles the project and powers its units on, stopped. Returns why it
    // cannot (the project has errors), empty when the simulation began.
    QString begin(ProjectDocument* document);
    // Back to editing: the simulation and its forces are dropped.
    void end();

    void start();
    void stop();
    void singleScan();
    // Power on again at time 0; forces stay.
    void reset();

    void setSpeed(double speed);
    double speed() const { return m_pacer.speed(); }
    void setUpdateInterval(int ms);
    int updateInterval() const { return m_updateMs; }

    State state() const;
    bool isActive() const { return m_simulation != nullptr; }
    ProjectDocument* document() const;
    const sim::Simulation* simulation() const { return m_simulation.get(); }
    const std::vector<compiler::UnitImage>& images() const { return m_images; }

    // As Simulation::set: an input takes the value as from the outside world,
    // anything else is forced.
    void set(const lang::Address& address, std::int64_t value);
    void force(const lang::Address& address, std::int64_t value);
    // One channel (1 or 2) of a safe AS-i input slave the unit's AS-i options define.
    void setChannel(const lang::Address& address, int channel, bool closed);
    void release(const lang::Address& address);
    void releaseAll();
    // A click on a contact: an input or a forced variable changes between 0
    // and 1; false for anything else (it needs a force first).
    bool toggle(const lang::Address& address);
    bool isForced(const lang::Address& address) const;
    // Every force of every unit, by address.
    std::vector<std::pair<lang::Address, std::int64_t>> forces() const;

    // Resolves a symbolic name or an address as a scenario does; the message
    // when it cannot.
    bool resolve(const QString& word, lang::Address& address, QString& error) const;
    // The same, with NAME.ch1 and NAME.ch2 for a channel of a safe AS-i slave
    // (`channel` 1 or 2, else 0).
    bool resolveChannel(const QString& word, lang::Address& address, int& channel,
                        QString& error) const;
    // The project's symbolic names and every operand of the compiled code, for completion.
    QStringList operandWords() const;

    // The project's gateways on the simulated bus, by node address: each
    // exchanges data with the units after every scan (docs/gateway.md).
    // Read them under gatewayMutex(): the Modbus service answers through
    // them on its own thread.
    const std::vector<std::unique_ptr<gateway::GatewayNode>>& gateways() const {
        return m_gateways;
    }
    std::mutex& gatewayMutex() const { return m_gatewayMutex; }
    // A Modbus request for the project's first Ethernet gateway (exception
    // 0B without one); safe on any thread.
    gateway::ModbusResponse answerModbus(const gateway::ModbusRequest& request);

    // What the waveform shows.
    sim::WaveformRecorder& recorder() { return m_recorder; }
    const sim::WaveformRecorder& recorder() const { return m_recorder; }

    struct ScenarioResult {
        struct Line {
            int line = 0;
            QString text; // the failure or diagnostic as the command line prints it
        };
        QString path;
        int passed = 0;
        int failed = 0;
        std::vector<Line> failures;     // failures and syntax errors, in file order
        lang::Diagnostics syntaxErrors; // the scenario did not run (also in failures)
        QString error;                  // the file cannot be read, or the project does not compile
        bool cancelled = false;
        std::int64_t endMs = 0; // the virtual time the run ended at
    };
    // Starts a scenario file from power on in a fresh simulation of the
    // project, on a thread of its own so that the window stays responsive:
    // scenarioProgress tells how far it got, cancelScenario stops it, and
    // scenarioFinished brings the result, after which the simulation shows
    // the state the scenario ended in (stopped). The waveform records the
    // run: everything the scenario touches and the program writes. A result
    // that needs no run (the file or the project has errors) comes at once.
    // False when a scenario runs already.
    bool startScenario(ProjectDocument* document, const QString& path);
    void cancelScenario();
    bool isRunningScenario() const { return m_job != nullptr; }
    // startScenario, waiting for the result while the events go on (the
    // command line, tests).
    ScenarioResult runScenario(ProjectDocument* document, const QString& path);

signals:
    void stateChanged();
    // Time to show the state again.
    void updated();
    void forcesChanged();
    // The simulation ended without the user asking (the project changed or closed).
    void endedBecause(const QString& reason);
    void scenarioStarted();
    // Virtual time reached of the most the scenario can run.
    void scenarioProgress(qint64 reachedMs, qint64 totalMs);
    void scenarioFinished(const rs::ui::SimulationSession::ScenarioResult& result);
    // The simulation began on another project than the last one, or the last
    // one closed: what was chosen for it (traces, watched variables, scenario
    // results) goes.
    void projectChanged();

private:
    struct ScenarioJob;
    void scenarioDone();
    ScenarioResult resultOf(const ScenarioJob& job) const;
    QString compile(ProjectDocument* document);
    void tick();
    void scanOnce();
    void changed();
    std::int64_t wallMs() const { return m_wall.elapsed(); }

    QPointer<ProjectDocument> m_document;
    // The project simulated last, compared only; it stays after the end, until it closes.
    const QObject* m_lastSimulated = nullptr;
    std::vector<compiler::UnitImage> m_images;
    std::unique_ptr<sim::Simulation> m_simulation;
    std::vector<std::unique_ptr<gateway::GatewayNode>> m_gateways;
    mutable std::mutex m_gatewayMutex;
    sim::RealTimePacer m_pacer;
    sim::WaveformRecorder m_recorder;
    QElapsedTimer m_wall;
    QTimer m_ticks;
    std::int64_t m_lastUpdateMs = 0;
    int m_updateMs = 100;
    // The scenario running on a worker: its own simulation and recording,
    // which become the session's when it ends; nothing of the project.
    std::shared_ptr<ScenarioJob> m_job;
    QFutureWatcher<void> m_jobWatcher;
    QTimer m_jobProgress;
};

} // namespace rs::ui
