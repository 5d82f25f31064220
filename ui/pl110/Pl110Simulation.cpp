// SPDX-License-Identifier: GPL-3.0-or-later
#include "pl110/Pl110Simulation.h"

#include "pl110/ModbusSlave.h"
#include "pl110/Pl110Document.h"
#include "pl110/Scenario.h"
#include "project/ProjectFile.h"

#include <QFileInfo>

namespace rs::ui {

namespace {

// At most this many scans per tick catch up with the wall clock: a machine
// too slow for real time runs slower instead of freezing the window.
constexpr int kMaxScansPerTick = 50;

bool isInput(const pl110::Address& address) {
    return address.area == pl110::Area::Input || address.area == pl110::Area::AnalogInput;
}

} // namespace

Pl110Simulation::Pl110Simulation(Pl110Document* document, QObject* parent)
    : QObject(parent), m_document(document) {
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &Pl110Simulation::tick);
    connect(document, &Pl110Document::changed, this, [this] {
        const bool wasRunning = isRunning();
        m_timer.stop();
        if (!m_engine)
            return;
        m_engine.reset();
        if (wasRunning)
            Q_EMIT stopped(tr("The program changed: the simulation stopped. Start it again to "
                              "run the new program."));
        Q_EMIT discarded();
    });
}

Pl110Simulation::~Pl110Simulation() = default;

QString Pl110Simulation::prepare(bool powerOn) {
    if (m_engine && !powerOn)
        return {};
    if (!m_document->isRunnable())
        return tr("The program has errors; fix them to simulate it.");
    m_engine = std::make_unique<pl110::ScanEngine>(m_document->program());
    m_engine->reset();
    // What the user held or forced before stays held: the same switches.
    for (const auto& [address, value] : m_forced) {
        if (isInput(address))
            m_engine->set(address, value);
        else
            m_engine->force(address, value);
    }
    m_recorder.clear();
    m_recorder.sample(*m_engine);
    return {};
}

QString Pl110Simulation::start() {
    if (isRunning())
        return {};
    if (QString error = prepare(false); !error.isEmpty())
        return error;
    m_clock.start();
    m_clockOffsetMs = m_engine->timeMs();
    m_timer.start(m_engine->cycleMs());
    Q_EMIT started();
    Q_EMIT scanned();
    return {};
}

void Pl110Simulation::stop() {
    if (!isRunning())
        return;
    m_timer.stop();
    Q_EMIT stopped({});
}

QString Pl110Simulation::singleScan() {
    stop();
    if (QString error = prepare(false); !error.isEmpty())
        return error;
    scanOnce();
    Q_EMIT scanned();
    return {};
}

QString Pl110Simulation::reset() {
    const bool wasRunning = isRunning();
    m_timer.stop();
    if (QString error = prepare(true); !error.isEmpty())
        return error;
    Q_EMIT scanned();
    if (wasRunning) {
        m_clock.start();
        m_clockOffsetMs = 0;
        m_timer.start(m_engine->cycleMs());
    }
    return {};
}

void Pl110Simulation::tick() {
    const std::int64_t due = m_clock.elapsed() + m_clockOffsetMs;
    int scans = 0;
    while (m_engine->timeMs() + m_engine->cycleMs() <= due && scans < kMaxScansPerTick) {
        scanOnce();
        ++scans;
    }
    if (scans == kMaxScansPerTick) // fell behind: virtual time goes on from now
        m_clockOffsetMs = m_engine->timeMs() - m_clock.elapsed();
    if (scans > 0)
        Q_EMIT scanned();
}

void Pl110Simulation::scanOnce() {
    m_engine->scan();
    m_recorder.sample(*m_engine);
}

bool Pl110Simulation::record(const pl110::Address& address) {
    return m_recorder.add(address, m_engine.get());
}

void Pl110Simulation::set(const pl110::Address& address, std::int64_t value) {
    m_forced[address] = value;
    if (!m_engine)
        return;
    if (isInput(address))
        m_engine->set(address, value);
    else
        m_engine->force(address, value);
    Q_EMIT scanned();
}

void Pl110Simulation::release(const pl110::Address& address) {
    m_forced.erase(address);
    if (!m_engine)
        return;
    if (isInput(address))
        m_engine->set(address, 0);
    else
        m_engine->release(address);
    Q_EMIT scanned();
}

QString Pl110Simulation::serveModbus(int slave) {
    stopServing();
    if (QString error = prepare(false); !error.isEmpty())
        return error;
    std::string error;
    m_modbus = pl110::ModbusRtuServer::open(slave, error);
    if (!m_modbus)
        return QString::fromStdString(error);
    m_modbusReadable =
        std::make_unique<QSocketNotifier>(m_modbus->descriptor(), QSocketNotifier::Read);
    connect(m_modbusReadable.get(), &QSocketNotifier::activated, this,
            &Pl110Simulation::answerModbus);
    Q_EMIT scanned();
    return {};
}

void Pl110Simulation::stopServing() {
    m_modbusReadable.reset();
    m_modbus.reset();
}

QString Pl110Simulation::modbusDevice() const {
    return m_modbus ? QString::fromStdString(m_modbus->devicePath()) : QString();
}

void Pl110Simulation::answerModbus() {
    // The frame has begun to arrive: the rest follows within the byte
    // timeout. A program with errors has nothing to answer from: exception
    // 4, server device failure.
    if (!m_engine && !prepare(false).isEmpty()) {
        m_modbus->serve(100, [](std::span<const std::uint8_t> request) {
            return std::vector<std::uint8_t>{
                static_cast<std::uint8_t>((request.empty() ? 0 : request[0]) | 0x80), 0x04};
        });
        return;
    }
    m_modbus->serve(100, [this](std::span<const std::uint8_t> request) {
        return pl110::answerRequest(m_engine->memory(), request);
    });
    Q_EMIT scanned();
}

Pl110Simulation::ScenarioRun Pl110Simulation::runScenario(const QString& path) {
    ScenarioRun run;
    stop();
    const project::FileText file = project::readTextFile(path);
    if (!file.error.isEmpty()) {
        run.error = file.error;
        return run;
    }
    // A scenario starts from power on with nothing set by hand.
    m_forced.clear();
    if (run.error = prepare(true); !run.error.isEmpty())
        return run;
    const pl110::Scenario scenario =
        pl110::parseScenario(file.text, pl110::ScenarioNames(m_document->program()));
    run.report =
        pl110::runScenario(QFileInfo(path).fileName().toStdString(), scenario, *m_engine,
                           [this](const pl110::ScanEngine& engine) { m_recorder.sample(engine); });
    Q_EMIT scanned();
    return run;
}

} // namespace rs::ui
