// SPDX-License-Identifier: GPL-3.0-or-later
// Modbus TCP request latency of a simulated Ethernet gateway (issue 20):
// unit 33 reads from 4 clients, 100 requests a second in all, while the
// generated 32-unit plant simulates in real time (docs/performance.md).
#include "ProjectGenerator.h"
#include "compiler/Compiler.h"
#include "gateway/GatewayNode.h"
#include "gateway/ModbusTcpServer.h"
#include "sim/Simulation.h"

#include <benchmark/benchmark.h>
#include <modbus/modbus.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kClients = 4;
constexpr auto kRequestInterval = std::chrono::milliseconds(40); // 25 a second per client

void BM_Unit33ReadLatency(benchmark::State& state) {
    const auto compiled =
        rs::compiler::compileText(rs::bench::generateProject({32, 2000, 20260101}));
    if (compiled.errors()) {
        state.SkipWithError("the generated plant does not compile");
        return;
    }
    rs::sim::Simulation simulation(compiled.images);
    std::string error;
    auto server = rs::gateway::ModbusTcpServer::listen("127.0.0.1", 0, error);
    if (!server) {
        state.SkipWithError(error.c_str());
        return;
    }
    std::atomic<bool> stop{false};
    std::mutex nodeMutex;
    rs::gateway::GatewayNode node(0, rs::project::Gateway{});
    node.exchange(simulation);
    std::thread modbus([&] {
        while (!stop)
            server->serve(
                50,
                [&](const rs::gateway::ModbusRequest& request) {
                    std::lock_guard lock(nodeMutex);
                    return node.answer(request);
                },
                [](const rs::gateway::ModbusTcpServer::ClientEvent&) {});
    });
    // The plant on the wall clock; a scan that starts a whole cycle late is late.
    std::int64_t scans = 0;
    std::int64_t lateScans = 0;
    std::thread plant([&] {
        const auto start = Clock::now();
        while (!stop) {
            const auto due = start + std::chrono::milliseconds(simulation.timeMs());
            std::this_thread::sleep_until(due);
            if (Clock::now() - due > std::chrono::milliseconds(simulation.cycleMs()))
                ++lateScans;
            simulation.scan();
            {
                std::lock_guard lock(nodeMutex);
                node.exchange(simulation);
            }
            ++scans;
        }
    });

    std::vector<double> latenciesUs;
    std::mutex latencyMutex;
    const auto seconds = std::chrono::seconds(state.range(0));
    for (auto _ : state) {
        std::vector<std::thread> clients;
        for (int c = 0; c < kClients; ++c)
            clients.emplace_back([&, c] {
                modbus_t* client = modbus_new_tcp("127.0.0.1", server->port());
                modbus_set_slave(client, rs::gateway::kDataFromPlutoUnit);
                if (modbus_connect(client) != 0) {
                    modbus_free(client);
                    return;
                }
                std::uint16_t registers[66];
                // Spread the clients over the interval, as independent clients are.
                auto next = Clock::now() + kRequestInterval * c / kClients;
                const auto end = Clock::now() + seconds;
                std::vector<double> mine;
                while (next < end) {
                    std::this_thread::sleep_until(next);
                    const auto sent = Clock::now();
                    if (modbus_read_registers(client, 1, 66, registers) == 66)
                        mine.push_back(
                            std::chrono::duration<double, std::micro>(Clock::now() - sent).count());
                    next += kRequestInterval;
                }
                modbus_close(client);
                modbus_free(client);
                std::lock_guard lock(latencyMutex);
                latenciesUs.insert(latenciesUs.end(), mine.begin(), mine.end());
            });
        for (auto& client : clients)
            client.join();
    }
    stop = true;
    plant.join();
    modbus.join();
    if (latenciesUs.empty()) {
        state.SkipWithError("no request was answered");
        return;
    }
    std::sort(latenciesUs.begin(), latenciesUs.end());
    const auto at = [&](double fraction) {
        return latenciesUs[static_cast<std::size_t>(fraction *
                                                    static_cast<double>(latenciesUs.size() - 1))];
    };
    state.counters["requests"] = static_cast<double>(latenciesUs.size());
    state.counters["median_us"] = at(0.5);
    state.counters["p99_us"] = at(0.99);
    state.counters["max_us"] = latenciesUs.back();
    state.counters["scans"] = static_cast<double>(scans);
    state.counters["late_scans"] = static_cast<double>(lateScans);
}

} // namespace

BENCHMARK(BM_Unit33ReadLatency)->Arg(10)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
