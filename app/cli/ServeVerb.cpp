// SPDX-License-Identifier: GPL-3.0-or-later
#include "ServeVerb.h"

#include "Verbs.h"
#include "gateway/GatewayNode.h"
#include "gateway/ModbusTcpServer.h"
#include "sim/ScenarioRunner.h"
#include "sim/Simulation.h"

#include <QString>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
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

// The simulation on the wall clock, `speed` times real time.
class Pacer {
public:
    Pacer(const sim::Simulation& simulation, double speed)
        : m_simulation(simulation), m_speed(speed), m_start(Clock::now()) {}

    // Sleeps until the next scan is due; false when asked to stop.
    bool waitForScan() const {
        const auto due = m_start + std::chrono::duration_cast<Clock::duration>(
                                       std::chrono::duration<double, std::milli>(
                                           static_cast<double>(m_simulation.timeMs()) / m_speed));
        while (!g_stop && Clock::now() < due)
            std::this_thread::sleep_for(
                std::min<Clock::duration>(due - Clock::now(), std::chrono::milliseconds(50)));
        return !g_stop;
    }

private:
    const sim::Simulation& m_simulation;
    double m_speed;
    Clock::time_point m_start;
};

} // namespace

int runServe(const Invocation& invocation) {
    if (invocation.arguments.size() != 1)
        return usage(QStringLiteral("serve takes exactly one FILE.sps"));
    const QString path = invocation.arguments[0];
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
    double speed = 1.0;
    if (invocation.options.isSet(QStringLiteral("speed"))) {
        bool ok = false;
        speed = invocation.options.value(QStringLiteral("speed")).toDouble(&ok);
        if (!ok || speed < 0.01 || speed > 1000)
            return usage(QStringLiteral("--speed takes a factor of real time, 0.01 to 1000"));
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
        if (!text.error.isEmpty()) {
            std::fprintf(stderr, "rungsmith-cli: %s\n", qPrintable(text.error));
            return UsageOrIo;
        }
        scenario = sim::parseScenario(text.text, sim::OperandNames(loaded.project));
        if (!scenario.diagnostics.empty()) {
            for (const auto& diagnostic : scenario.diagnostics)
                std::fprintf(
                    stderr, "%s\n",
                    lang::formatDiagnostic(scenarioPath.toStdString(), diagnostic).c_str());
            return Failed;
        }
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
    const Pacer pacer(simulation, speed);
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
