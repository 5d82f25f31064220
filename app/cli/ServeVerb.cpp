// SPDX-License-Identifier: GPL-3.0-or-later
#include "ServeVerb.h"

#include "Pl110Verbs.h"
#include "Verbs.h"
#include "gateway/GatewayNode.h"
#include "gateway/ModbusTcpServer.h"
#include "pl110/ModbusRtuServer.h"
#include "pl110/ModbusSlave.h"
#include "pl110/ProgramText.h"
#include "pl110/ScanEngine.h"
#include "pl110/Scenario.h"
#include "project/ProjectFile.h"
#include "sim/ScenarioRunner.h"
#include "sim/Simulation.h"

#include <QString>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <functional>
#include <mutex>
#include <thread>

namespace rs::cli {

namespace {

using Clock = std::chrono::steady_clock;

std::atomic<bool> g_stop{false};

extern "C" void requestStop(int) {
    g_stop = true;
}

void onStopSignals() {
    struct sigaction action {};
    action.sa_handler = requestStop;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

// Lines from the simulation and from the server's thread, whole.
class Output {
public:
    void line(const std::string& text) {
        std::lock_guard lock(m_mutex);
        std::fprintf(stdout, "%s\n", text.c_str());
        std::fflush(stdout);
    }

private:
    std::mutex m_mutex;
};

// A simulation on the wall clock, `speed` times real time: `virtualTimeMs`
// tells how far it has run.
class Pacer {
public:
    Pacer(std::function<std::int64_t()> virtualTimeMs, double speed)
        : m_virtualTimeMs(std::move(virtualTimeMs)), m_speed(speed), m_start(Clock::now()) {}

    // Sleeps until the next scan is due; false when asked to stop.
    bool waitForScan() const {
        const auto due = m_start + std::chrono::duration_cast<Clock::duration>(
                                       std::chrono::duration<double, std::milli>(
                                           static_cast<double>(m_virtualTimeMs()) / m_speed));
        while (!g_stop && Clock::now() < due)
            std::this_thread::sleep_for(
                std::min<Clock::duration>(due - Clock::now(), std::chrono::milliseconds(50)));
        return !g_stop;
    }

private:
    std::function<std::int64_t()> m_virtualTimeMs;
    double m_speed;
    Clock::time_point m_start;
};

int unreadable(const QString& error) {
    std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(error));
    return UsageOrIo;
}

// A scenario with syntax errors is not served: its errors, and Failed.
int badScenario(const QString& path, const lang::Diagnostics& diagnostics) {
    for (const auto& diagnostic : diagnostics)
        std::fprintf(stderr, "%s\n",
                     lang::formatDiagnostic(path.toStdString(), diagnostic).c_str());
    return Failed;
}

// serve PL110.sps --modbus-rtu: the program scanned in real time, its
// Modbus RTU slave map on a pseudo-terminal (docs/pl110.md, "Modbus"); with
// a scenario, its `set` lines drive the inputs on the simulated clock.
int servePl110(const QString& path, const std::string& text, int slave, double speed,
               const QString& scenarioPath) {
    auto program = checkedPl110(path, text);
    if (!program)
        return Failed;
    pl110::Scenario scenario;
    if (!scenarioPath.isEmpty()) {
        const project::FileText read = project::readTextFile(scenarioPath);
        if (!read.error.isEmpty())
            return unreadable(read.error);
        scenario = pl110::parseScenario(read.text, pl110::ScenarioNames(*program));
        if (!scenario.diagnostics.empty())
            return badScenario(scenarioPath, scenario.diagnostics);
    }
    std::string error;
    auto server = pl110::ModbusRtuServer::open(slave, error);
    if (!server) {
        std::fprintf(stderr, "rungsmith-cli: %s\n", error.c_str());
        return UsageOrIo;
    }
    onStopSignals();
    Output output;
    output.line("serving Modbus RTU on " + server->devicePath() + " as slave " +
                std::to_string(slave));
    pl110::ScanEngine engine(std::move(*program));
    std::mutex memoryMutex; // the scan and a request's answer take turns
    std::thread modbus([&] {
        while (!g_stop)
            server->serve(100, [&](std::span<const std::uint8_t> request) {
                std::lock_guard lock(memoryMutex);
                return pl110::answerRequest(engine.memory(), request);
            });
    });
    const Pacer pacer([&] { return engine.timeMs(); }, speed);
    {
        // The scenario's scans hold the memory; the wait for the wall clock
        // lets the Modbus thread answer.
        std::unique_lock lock(memoryMutex);
        const sim::ScenarioReport report = pl110::runScenario(
            scenarioPath.toStdString(), scenario, engine,
            [&](const pl110::ScanEngine&) {
                lock.unlock();
                pacer.waitForScan();
                lock.lock();
            },
            [] { return g_stop.load(); });
        for (const auto& failure : report.failures)
            output.line(failure);
    }
    while (pacer.waitForScan()) {
        std::lock_guard lock(memoryMutex);
        engine.scan();
    }
    modbus.join();
    output.line("stopped");
    return Ok;
}

} // namespace

int runServe(const Invocation& invocation) {
    if (invocation.arguments.size() != 1)
        return usage(QStringLiteral("serve takes exactly one FILE.sps"));
    const QString path = invocation.arguments[0];
    double speed = 1.0;
    if (invocation.options.isSet(QStringLiteral("speed"))) {
        bool ok = false;
        speed = invocation.options.value(QStringLiteral("speed")).toDouble(&ok);
        if (!ok || speed < 0.01 || speed > 1000)
            return usage(QStringLiteral("--speed takes a factor of real time, 0.01 to 1000"));
    }
    if (invocation.options.isSet(QStringLiteral("modbus-rtu"))) {
        int slave = 1;
        if (invocation.options.isSet(QStringLiteral("slave"))) {
            bool ok = false;
            slave = invocation.options.value(QStringLiteral("slave")).toInt(&ok);
            if (!ok || slave < 1 || slave > 247)
                return usage(QStringLiteral("--slave takes a Modbus slave address, 1 to 247"));
        }
        const project::FileText text = project::readTextFile(path);
        if (!text.error.isEmpty()) {
            std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(text.error));
            return UsageOrIo;
        }
        if (!pl110::isPl110Text(text.text))
            return usage(QStringLiteral("--modbus-rtu serves a PL110 program ($target PL110); "
                                        "a Pluto project is served over Modbus TCP (--modbus)"));
        return servePl110(path, text.text, slave, speed,
                          invocation.options.value(QStringLiteral("scenario")));
    }
    QString host = QStringLiteral("127.0.0.1");
    int port = 1502;
    if (invocation.options.isSet(QStringLiteral("modbus"))) {
        const QString address = invocation.options.value(QStringLiteral("modbus"));
        const qsizetype colon = address.lastIndexOf(QLatin1Char(':'));
        bool ok = colon > 0;
        port = ok ? address.mid(colon + 1).toInt(&ok) : 0;
        if (!ok || port < 0 || port > 65535)
            return usage(QStringLiteral("--modbus takes HOST:PORT, as 127.0.0.1:1502"));
        host = address.left(colon);
    }
    const LoadedProject loaded = loadProject(path, libraryFiles(invocation));
    if (loaded.status != Ok)
        return loaded.status;
    compiler::CompileResult compiled = rs::cli::compiled(loaded, {});
    if (compiled.errors()) {
        printDiagnostics(path, compiled.diagnostics);
        std::fprintf(stdout, "%d Error(s) detected Result=FAILED\n", compiled.errors());
        return Failed;
    }
    const auto gateway =
        std::find_if(loaded.project.gateways.begin(), loaded.project.gateways.end(),
                     [](const auto& entry) { return project::servesModbusTcp(entry.second.type); });
    if (gateway == loaded.project.gateways.end()) {
        std::fprintf(stderr,
                     "rungsmith-cli: %s has no Ethernet gateway to serve; declare one as "
                     ";@gateway 0 type=\"GATE-E1\" (docs/gateway.md)\n",
                     qPrintable(path));
        return UsageOrIo;
    }
    sim::Scenario scenario;
    const QString scenarioPath = invocation.options.value(QStringLiteral("scenario"));
    if (!scenarioPath.isEmpty()) {
        const project::FileText text = project::readTextFile(scenarioPath);
        if (!text.error.isEmpty())
            return unreadable(text.error);
        scenario = sim::parseScenario(text.text, sim::OperandNames(loaded.project));
        if (!scenario.diagnostics.empty())
            return badScenario(scenarioPath, scenario.diagnostics);
    }

    std::string error;
    auto server = gateway::ModbusTcpServer::listen(host.toStdString(), port, error);
    if (!server) {
        std::fprintf(stderr, "rungsmith-cli: %s\n", error.c_str());
        return UsageOrIo;
    }
    onStopSignals();
    Output output;
    output.line("serving Modbus TCP on " + host.toStdString() + ":" +
                std::to_string(server->port()) + " for gateway " + std::to_string(gateway->first) +
                " (" + std::string(project::gatewayTypeName(gateway->second.type)) + ")");

    sim::Simulation simulation(compiled.images);
    // The server's thread answers and the scans exchange under one lock; an
    // exchange is short (a copy of unit 33), so a scan never waits long.
    std::mutex nodeMutex;
    gateway::GatewayNode node(gateway->first, gateway->second);
    node.exchange(simulation);
    std::thread modbus([&] {
        while (!g_stop)
            server->serve(
                100,
                [&](const gateway::ModbusRequest& request) {
                    std::lock_guard lock(nodeMutex);
                    return node.answer(request);
                },
                [&](const gateway::ModbusTcpServer::ClientEvent& event) {
                    output.line(event.text);
                });
    });
    const auto publish = [&] {
        std::lock_guard lock(nodeMutex);
        node.exchange(simulation);
    };
    const Pacer pacer([&] { return simulation.timeMs(); }, speed);
    // The scenario runs as `test` runs it, each scan waiting for the wall clock.
    const sim::ScenarioReport report = sim::runScenario(
        scenarioPath.toStdString(), scenario, simulation, nullptr,
        [&](const sim::Simulation&) {
            publish();
            pacer.waitForScan();
        },
        [] { return g_stop.load(); });
    for (const auto& failure : report.failures)
        output.line(failure);
    while (pacer.waitForScan()) {
        simulation.scan();
        publish();
    }
    modbus.join();
    output.line("stopped");
    return Ok;
}

} // namespace rs::cli
