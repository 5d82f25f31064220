// SPDX-License-Identifier: GPL-3.0-or-later
#include "SimulationSession.h"

#include "compiler/Compiler.h"
#include "document/ProjectDocument.h"
#include "project/ProjectFile.h"
#include "project/RemanentVariables.h"
#include "project/VariableTable.h"
#include "sim/Scenario.h"

#include <QEventLoop>
#include <QFileInfo>
#include <QtConcurrent/QtConcurrentRun>

#include <atomic>
#include <optional>
#include <set>

namespace rs::ui {

namespace {

// The clock's timer: often enough for real time at a 10 ms cycle.
constexpr int kTickMs = 5;
// Scans run on the window's thread, so a tick may take only this long,
// leaving the rest of the time to painting and the user.
constexpr std::int64_t kTickBudgetMs = 4;
constexpr int kMaxScansPerTick = 2000;
// How often a running scenario's progress is shown.
constexpr int kProgressMs = 100;

std::unique_ptr<sim::Simulation> powerOn(const std::vector<compiler::UnitImage>& images,
                                         const project::Project& project) {
    auto simulation = std::make_unique<sim::Simulation>(images);
    for (int station : simulation->stations()) {
        const std::set<lang::Address> remanent = project::remanentOf(project, station);
        simulation->setRemanent(station, {remanent.begin(), remanent.end()});
    }
    simulation->restart();
    return simulation;
}

// The project's gateways, fresh, having taken the bus as the simulation stands.
std::vector<std::unique_ptr<gateway::GatewayNode>> gatewayNodes(const project::Project& project,
                                                                sim::Simulation& simulation) {
    std::vector<std::unique_ptr<gateway::GatewayNode>> nodes;
    for (const auto& [node, settings] : project.gateways) {
        nodes.push_back(std::make_unique<gateway::GatewayNode>(node, settings));
        nodes.back()->exchange(simulation);
    }
    return nodes;
}

} // namespace

struct SimulationSession::ScenarioJob {
    QString path;
    sim::Scenario scenario;
    std::unique_ptr<sim::Simulation> simulation;
    sim::WaveformRecorder recorder;
    std::int64_t totalMs = 0;
    sim::ScenarioReport report;
    std::atomic<bool> cancel = false;
    std::atomic<std::int64_t> reachedMs = 0;
};

SimulationSession::SimulationSession(QObject* parent) : QObject(parent) {
    m_ticks.setInterval(kTickMs);
    m_ticks.setTimerType(Qt::PreciseTimer);
    connect(&m_ticks, &QTimer::timeout, this, &SimulationSession::tick);
    m_jobProgress.setInterval(kProgressMs);
    connect(&m_jobProgress, &QTimer::timeout, this, [this] {
        if (m_job)
            emit scenarioProgress(m_job->reachedMs, m_job->totalMs);
    });
    connect(&m_jobWatcher, &QFutureWatcher<void>::finished, this, &SimulationSession::scenarioDone);
    m_wall.start();
}

SimulationSession::~SimulationSession() {
    if (m_job) {
        m_job->cancel = true;
        m_jobWatcher.waitForFinished();
    }
}

QString SimulationSession::compile(ProjectDocument* document) {
    if (!document)
        return tr("No project is open.");
    if (document->isDamaged())
        return tr("The project's text has errors; fix them before simulating.");
    compiler::CompileResult result = compiler::compile(document->project());
    if (result.errors())
        return tr("The project has %n error(s); compile it (F7) to see them.", nullptr,
                  result.errors());
    if (result.images.empty())
        return tr("The project has no Pluto to simulate.");
    if (m_document != document) {
        if (m_document)
            disconnect(m_document, nullptr, this, nullptr);
        m_document = document;
        connect(document, &ProjectDocument::changed, this, [this] {
            end();
            emit endedBecause(tr("The project changed, so the simulation ended. Start it again "
                                 "to simulate the new version."));
        });
        connect(document, &QObject::destroyed, this, [this] {
            end();
            emit endedBecause(tr("The project was closed, so the simulation ended."));
        });
    }
    m_images = std::move(result.images);
    return {};
}

QString SimulationSession::begin(ProjectDocument* document) {
    if (isActive() && document == m_document)
        return {};
    end();
    if (QString error = compile(document); !error.isEmpty())
        return error;
    m_simulation = powerOn(m_images, document->project());
    {
        std::lock_guard lock(m_gatewayMutex);
        m_gateways = gatewayNodes(document->project(), *m_simulation);
    }
    if (document != m_lastSimulated) {
        m_lastSimulated = document;
        connect(document, &QObject::destroyed, this, [this](QObject* gone) {
            if (gone != m_lastSimulated)
                return;
            m_lastSimulated = nullptr;
            m_recorder.removeAll();
            emit projectChanged();
        });
        m_recorder.removeAll();
        emit projectChanged();
    }
    m_recorder.clear();
    m_recorder.sample(*m_simulation);
    emit stateChanged();
    emit forcesChanged();
    emit updated();
    return {};
}

void SimulationSession::end() {
    std::optional<ScenarioResult> cancelled;
    if (m_job) {
        // The run is of the simulation that goes: it stops, and says so.
        m_job->cancel = true;
        m_jobWatcher.waitForFinished();
        m_jobProgress.stop();
        cancelled = resultOf(*m_job);
        m_job.reset();
    }
    m_ticks.stop();
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = nullptr;
    if (m_simulation) {
        {
            std::lock_guard lock(m_gatewayMutex);
            m_gateways.clear();
        }
        m_simulation.reset();
        m_images.clear();
        emit stateChanged();
        emit forcesChanged();
        emit updated();
    }
    if (cancelled)
        emit scenarioFinished(*cancelled);
}

ProjectDocument* SimulationSession::document() const {
    return m_document;
}

SimulationSession::State SimulationSession::state() const {
    if (!m_simulation)
        return State::Off;
    return m_ticks.isActive() ? State::Running : State::Stopped;
}

void SimulationSession::start() {
    if (!m_simulation || m_ticks.isActive())
        return;
    m_pacer.start(wallMs(), m_simulation->timeMs());
    m_lastUpdateMs = wallMs();
    m_ticks.start();
    emit stateChanged();
}

void SimulationSession::stop() {
    if (!m_ticks.isActive())
        return;
    m_ticks.stop();
    emit stateChanged();
    emit updated();
}

void SimulationSession::singleScan() {
    if (!m_simulation)
        return;
    stop();
    scanOnce();
    emit updated();
}

void SimulationSession::reset() {
    if (!m_simulation)
        return;
    m_simulation->restart();
    if (m_document) {
        std::lock_guard lock(m_gatewayMutex);
        m_gateways = gatewayNodes(m_document->project(), *m_simulation);
    }
    m_pacer.start(wallMs(), 0);
    m_recorder.clear();
    m_recorder.sample(*m_simulation);
    emit updated();
}

void SimulationSession::setSpeed(double speed) {
    m_pacer.setSpeed(speed, wallMs(), m_simulation ? m_simulation->timeMs() : 0);
}

void SimulationSession::setUpdateInterval(int ms) {
    m_updateMs = std::max(ms, 1);
}

void SimulationSession::scanOnce() {
    m_simulation->scan();
    if (!m_gateways.empty()) {
        std::lock_guard lock(m_gatewayMutex);
        for (auto& node : m_gateways)
            node->exchange(*m_simulation);
    }
    m_recorder.sample(*m_simulation);
}

void SimulationSession::tick() {
    const std::int64_t begun = wallMs();
    const int due =
        m_pacer.scansDue(begun, m_simulation->timeMs(), m_simulation->cycleMs(), kMaxScansPerTick);
    for (int i = 0; i < due; ++i) {
        scanOnce();
        // Behind the clock (or as fast as possible): the pacer drops what is left over.
        if (wallMs() - begun >= kTickBudgetMs)
            break;
    }
    const std::int64_t now = wallMs();
    if (now - m_lastUpdateMs >= m_updateMs) {
        m_lastUpdateMs = now;
        emit updated();
    }
}

gateway::ModbusResponse SimulationSession::answerModbus(const gateway::ModbusRequest& request) {
    std::lock_guard lock(m_gatewayMutex);
    for (auto& node : m_gateways)
        if (project::servesModbusTcp(node->settings().type))
            return node->answer(request);
    return {gateway::ModbusException::GatewayTargetFailed, {}};
}

void SimulationSession::changed() {
    emit forcesChanged();
    emit updated();
}

void SimulationSession::set(const lang::Address& address, std::int64_t value) {
    if (!m_simulation)
        return;
    m_recorder.add(address, m_simulation.get());
    m_simulation->set(address, value);
    changed();
}

void SimulationSession::setChannel(const lang::Address& address, int channel, bool closed) {
    if (!m_simulation || !m_simulation->setChannel(address, channel, closed))
        return;
    m_recorder.add(address, m_simulation.get());
    changed();
}

void SimulationSession::force(const lang::Address& address, std::int64_t value) {
    if (!m_simulation)
        return;
    m_recorder.add(address, m_simulation.get());
    m_simulation->force(address, value);
    changed();
}

void SimulationSession::release(const lang::Address& address) {
    if (!m_simulation)
        return;
    m_simulation->release(address);
    changed();
}

void SimulationSession::releaseAll() {
    for (const auto& [address, value] : forces())
        m_simulation->release(address);
    changed();
}

bool SimulationSession::toggle(const lang::Address& address) {
    if (!m_simulation || !address.isBit())
        return false;
    const std::int64_t flipped = m_simulation->value(address) ? 0 : 1;
    if (isForced(address))
        force(address, flipped);
    else if (sim::isOutsideValue(address))
        set(address, flipped);
    else
        return false;
    return true;
}

bool SimulationSession::isForced(const lang::Address& address) const {
    const sim::UnitEngine* unit = m_simulation ? m_simulation->unit(address.unit) : nullptr;
    return unit && unit->forces().count(address) != 0;
}

std::vector<std::pair<lang::Address, std::int64_t>> SimulationSession::forces() const {
    std::vector<std::pair<lang::Address, std::int64_t>> all;
    if (!m_simulation)
        return all;
    for (int station : m_simulation->stations())
        for (const auto& force : m_simulation->unit(station)->forces())
            all.push_back(force);
    return all;
}

bool SimulationSession::resolve(const QString& word, lang::Address& address, QString& error) const {
    if (!m_document) {
        error = tr("The simulation is not running.");
        return false;
    }
    std::string message;
    if (sim::OperandNames(m_document->project())
            .resolve(word.trimmed().toStdString(), address, message))
        return true;
    error = QString::fromStdString(message);
    return false;
}

bool SimulationSession::resolveChannel(const QString& word, lang::Address& address, int& channel,
                                       QString& error) const {
    if (!m_document) {
        error = tr("The simulation is not running.");
        return false;
    }
    std::string message;
    if (sim::OperandNames(m_document->project())
            .resolveChannel(word.trimmed().toStdString(), address, channel, message))
        return true;
    error = QString::fromStdString(message);
    return false;
}

QStringList SimulationSession::operandWords() const {
    std::set<QString> words;
    if (m_document) {
        const project::Project& project = m_document->project();
        for (int station : project.stations())
            for (const lang::Address& address : project::namedAddresses(project, station))
                words.insert(QString::fromStdString(project::variableName(project, address)));
    }
    for (const auto& image : m_images) {
        for (const auto& instruction : image.code)
            if (instruction.operand.valid())
                words.insert(QString::fromStdString(lang::toString(instruction.operand)));
        // The two channels of each safe AS-i slave, by address and by name.
        for (const auto& slave : image.asi.slaves) {
            const lang::Address input{lang::AddressKind::AsiInput, image.station, slave.number};
            if (!m_simulation || !m_simulation->hasChannels(input))
                continue;
            QStringList stems{QString::fromStdString(lang::toString(input))};
            if (m_document)
                if (const std::string name = project::variableName(m_document->project(), input);
                    !name.empty())
                    stems << QString::fromStdString(name);
            for (const QString& stem : stems)
                for (const char* channel : {".ch1", ".ch2"})
                    words.insert(stem + QLatin1String(channel));
        }
    }
    return {words.begin(), words.end()};
}

bool SimulationSession::startScenario(ProjectDocument* document, const QString& path) {
    if (m_job)
        return false;
    ScenarioResult failed;
    failed.path = path;
    const project::FileText file = project::readTextFile(path);
    if (!file.error.isEmpty()) {
        failed.error = file.error;
        emit scenarioFinished(failed);
        return true;
    }
    if (!isActive() || document != m_document) {
        if (QString error = begin(document); !error.isEmpty()) {
            failed.error = error;
            emit scenarioFinished(failed);
            return true;
        }
    }
    stop();
    // Everything the worker needs is made here, from the project, which the
    // worker never sees.
    auto job = std::make_shared<ScenarioJob>();
    job->path = path;
    job->scenario = sim::parseScenario(file.text, sim::OperandNames(document->project()));
    job->simulation = powerOn(m_images, document->project());
    job->totalMs = sim::scenarioLengthMs(job->scenario, job->simulation->cycleMs());
    job->recorder = m_recorder;
    for (const lang::Address& address : sim::traceSignals(m_images, sim::touchedBy(job->scenario)))
        job->recorder.add(address);
    job->recorder.clear();
    m_job = job;
    m_jobWatcher.setFuture(QtConcurrent::run([job] {
        job->report = sim::runScenario(
            QFileInfo(job->path).fileName().toStdString(), job->scenario, *job->simulation, nullptr,
            [&run = *job](const sim::Simulation& simulation) {
                run.recorder.sample(simulation);
                run.reachedMs.store(simulation.timeMs(), std::memory_order_relaxed);
            },
            [&run = *job] { return run.cancel.load(std::memory_order_relaxed); });
    }));
    m_jobProgress.start();
    emit scenarioStarted();
    emit scenarioProgress(0, job->totalMs);
    return true;
}

void SimulationSession::cancelScenario() {
    if (m_job)
        m_job->cancel = true;
}

SimulationSession::ScenarioResult SimulationSession::resultOf(const ScenarioJob& job) const {
    ScenarioResult result;
    result.path = job.path;
    result.passed = job.report.passed;
    result.failed = job.report.failed;
    result.cancelled = job.report.cancelled;
    result.endMs = job.reachedMs;
    result.syntaxErrors = job.scenario.diagnostics;
    const auto& diagnostics = job.report.diagnostics;
    for (std::size_t i = 0; i < diagnostics.size() && i < job.scenario.diagnostics.size(); ++i)
        result.failures.push_back(
            {job.scenario.diagnostics[i].line, QString::fromStdString(diagnostics[i])});
    for (std::size_t i = 0; i < job.report.failures.size(); ++i)
        result.failures.push_back(
            {job.report.failureLines[i], QString::fromStdString(job.report.failures[i])});
    return result;
}

void SimulationSession::scenarioDone() {
    // A run that end() took back already, or a finish meant for an earlier run.
    if (!m_job || !m_jobWatcher.isFinished())
        return;
    m_jobProgress.stop();
    const std::shared_ptr<ScenarioJob> job = std::exchange(m_job, nullptr);
    const ScenarioResult result = resultOf(*job);
    m_simulation = std::move(job->simulation);
    if (m_document) {
        std::lock_guard lock(m_gatewayMutex);
        m_gateways = gatewayNodes(m_document->project(), *m_simulation);
    }
    m_recorder = std::move(job->recorder);
    m_pacer.start(wallMs(), m_simulation->timeMs());
    emit stateChanged();
    emit forcesChanged();
    emit updated();
    emit scenarioFinished(result);
}

SimulationSession::ScenarioResult SimulationSession::runScenario(ProjectDocument* document,
                                                                 const QString& path) {
    std::optional<ScenarioResult> finished;
    QEventLoop loop;
    const auto connection = connect(this, &SimulationSession::scenarioFinished, &loop,
                                    [&](const ScenarioResult& result) {
                                        finished = result;
                                        loop.quit();
                                    });
    if (!startScenario(document, path)) {
        disconnect(connection);
        ScenarioResult busy;
        busy.path = path;
        busy.error = tr("A scenario is running already.");
        return busy;
    }
    if (!finished)
        loop.exec();
    disconnect(connection);
    return *finished;
}

} // namespace rs::ui
