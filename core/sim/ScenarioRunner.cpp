// SPDX-License-Identifier: GPL-3.0-or-later
#include "ScenarioRunner.h"

#include <algorithm>
#include <cstdio>
#include <limits>

namespace rs::sim {

namespace {

std::string seconds(std::int64_t ms) {
    char text[32];
    std::snprintf(text, sizeof text, "%lld.%03llds", static_cast<long long>(ms / 1000),
                  static_cast<long long>(ms % 1000));
    return text;
}

} // namespace

std::vector<lang::Address> touchedBy(const Scenario& scenario) {
    std::vector<lang::Address> touched;
    for (const auto& step : scenario.steps)
        if (step.kind == ScenarioStep::Kind::Set || step.kind == ScenarioStep::Kind::Release ||
            step.kind == ScenarioStep::Kind::Expect)
            touched.push_back(step.operand);
    return touched;
}

ScenarioReport runScenario(const std::string& fileName, const Scenario& scenario,
                           Simulation& simulation, VcdTrace* trace, const ScanObserver& observer,
                           const CancelRequest& cancelled) {
    ScenarioReport report;
    if (!scenario.diagnostics.empty()) {
        for (const auto& diagnostic : scenario.diagnostics)
            report.diagnostics.push_back(lang::formatDiagnostic(fileName, diagnostic));
        report.failed = 1;
        return report;
    }
    simulation.restart();
    auto sample = [&] {
        if (trace)
            trace->sample(simulation);
        if (observer)
            observer(simulation);
    };
    sample();
    // False once the caller cancels; the loops end at the scan it was asked after.
    auto scan = [&] {
        simulation.scan();
        sample();
        if (cancelled && cancelled())
            report.cancelled = true;
        return !report.cancelled;
    };
    for (const auto& step : scenario.steps) {
        if (report.cancelled)
            break;
        switch (step.kind) {
        case ScenarioStep::Kind::Cycle:
            simulation.setCycleMs(static_cast<int>(step.durationMs));
            break;
        case ScenarioStep::Kind::Set:
            if (step.channel)
                simulation.setChannel(step.operand, step.channel, step.value != 0);
            else
                simulation.set(step.operand, step.value);
            break;
        case ScenarioStep::Kind::Release:
            simulation.release(step.operand);
            break;
        case ScenarioStep::Kind::Disconnect:
        case ScenarioStep::Kind::Connect:
            simulation.setOnBus(static_cast<int>(step.value),
                                step.kind == ScenarioStep::Kind::Connect);
            break;
        case ScenarioStep::Kind::Run: {
            const std::int64_t end = simulation.timeMs() + step.durationMs;
            while (simulation.timeMs() < end && scan()) {
            }
            break;
        }
        case ScenarioStep::Kind::Scans:
            for (std::int64_t i = 0; i < step.count && scan(); ++i) {
            }
            break;
        case ScenarioStep::Kind::Expect: {
            const std::int64_t deadline = simulation.timeMs() + step.durationMs;
            bool held = simulation.value(step.operand) == step.value;
            while (!held && simulation.timeMs() < deadline && scan())
                held = simulation.value(step.operand) == step.value;
            if (report.cancelled && !held)
                break;
            if (held) {
                ++report.passed;
                break;
            }
            ++report.failed;
            report.failureLines.push_back(step.line);
            report.failures.push_back(fileName + ":" + std::to_string(step.line) + ": " +
                                      step.text +
                                      " failed: " + (step.durationMs ? "still " : "got ") +
                                      std::to_string(simulation.value(step.operand)) +
                                      " at t=" + seconds(simulation.timeMs()));
            break;
        }
        }
    }
    return report;
}

std::int64_t scenarioLengthMs(const Scenario& scenario, int cycleMs) {
    constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
    std::int64_t total = 0;
    // Saturating: the figure is for a progress bar, whatever the file says.
    auto add = [&](std::int64_t ms) {
        total = ms > kMax - total ? kMax : total + std::max<std::int64_t>(ms, 0);
    };
    for (const auto& step : scenario.steps) {
        switch (step.kind) {
        case ScenarioStep::Kind::Cycle:
            cycleMs = static_cast<int>(step.durationMs);
            break;
        case ScenarioStep::Kind::Run:
        case ScenarioStep::Kind::Expect:
            add(step.durationMs);
            break;
        case ScenarioStep::Kind::Scans:
            add(cycleMs > 0 && step.count > kMax / cycleMs ? kMax : step.count * cycleMs);
            break;
        case ScenarioStep::Kind::Set:
        case ScenarioStep::Kind::Release:
        case ScenarioStep::Kind::Disconnect:
        case ScenarioStep::Kind::Connect:
            break;
        }
    }
    return total;
}

} // namespace rs::sim
