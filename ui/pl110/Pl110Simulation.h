// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "pl110/ModbusRtuServer.h"
#include "pl110/ScanEngine.h"
#include "pl110/WaveformRecorder.h"
#include "sim/ScenarioRunner.h"
#endif

#include <QElapsedTimer>
#include <QObject>
#include <QSocketNotifier>
#include <QTimer>

#include <map>
#include <memory>

namespace rs::ui {

class Pl110Document;

// The simulated PL110 of a document: its scan engine running on a timer in
// step with the wall clock, the inputs the user sets, the forces, and
// scenarios run to their end. A change to the program stops it: what runs
// is always the program shown.
class Pl110Simulation : public QObject {
    Q_OBJECT
public:
    explicit Pl110Simulation(Pl110Document* document, QObject* parent = nullptr);
    ~Pl110Simulation() override;

    // Runs on from where it stands, or from power on when nothing has run
    // since the program last changed; an empty string, or why it cannot (the
    // program has errors).
    QString start();
    // Holds the program and the clock; the state stays shown.
    void stop();
    // One scan, stopped; the same answer as start().
    QString singleScan();
    // Power on again at time 0; what the user set or forced stays.
    QString reset();
    bool isRunning() const { return m_timer.isActive(); }
    // The engine of the running or last run, or nothing before the first.
    const pl110::ScanEngine* engine() const { return m_engine.get(); }

    // An input as from its terminal, or any other variable forced.
    void set(const pl110::Address& address, std::int64_t value);
    void release(const pl110::Address& address);
    bool isForced(const pl110::Address& address) const { return m_forced.contains(address); }

    // What the chosen variables did, scan by scan, since power on.
    pl110::WaveformRecorder& recorder() { return m_recorder; }
    const pl110::WaveformRecorder& recorder() const { return m_recorder; }
    // Records a variable from now on; false when it is recorded already.
    bool record(const pl110::Address& address);
    const std::map<pl110::Address, std::int64_t>& forced() const { return m_forced; }

    // Answers Modbus RTU requests (the datasheet's slave map) on a
    // pseudo-terminal as slave `slave`, from the engine's memory, whether
    // the simulation runs or stands; an empty string, or why it cannot.
    QString serveModbus(int slave);
    void stopServing();
    // The device a client opens, empty when not serving.
    QString modbusDevice() const;

    struct ScenarioRun {
        QString error; // the file could not be read, or the program has errors
        sim::ScenarioReport report;
    };
    // Runs a scenario file from power on to its end on virtual time; the
    // engine then shows where it ended, stopped.
    ScenarioRun runScenario(const QString& path);

Q_SIGNALS:
    void started();
    // The engine ran one or more scans (or was set): the live pages redraw.
    void scanned();
    // It stopped; `why` is empty when the user stopped it.
    void stopped(const QString& why);
    // The program changed: what ran is gone and the live pages show nothing.
    void discarded();

private:
    void tick();
    void scanOnce();
    void answerModbus();
    // An engine at power on with the user's inputs and forces, unless one runs
    // the current program already.
    QString prepare(bool powerOn);

    Pl110Document* m_document;
    std::unique_ptr<pl110::ScanEngine> m_engine;
    std::map<pl110::Address, std::int64_t> m_forced; // inputs set count too: the user holds them
    pl110::WaveformRecorder m_recorder;
    std::unique_ptr<pl110::ModbusRtuServer> m_modbus;
    std::unique_ptr<QSocketNotifier> m_modbusReadable;
    QTimer m_timer;
    QElapsedTimer m_clock;
    std::int64_t m_clockOffsetMs = 0; // virtual time minus wall-clock time since start
};

} // namespace rs::ui
