// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ScenarioRunner.h"

#include <cstdio>
#include <functional>
#include <string>
#include <type_traits>

// Running a scenario on any target's simulation (ScenarioRunner.h for what a
// run reports). The plant provides restart(), scan(), timeMs(),
// setCycleMs(int), set(Operand, value), setChannel(Operand, channel, on),
// release(Operand), setOnBus(unit, on) and value(Operand); `sample` sees it
// at power on and after every scan.
namespace rs::sim {

// "1.250s"
inline std::string scenarioSeconds(std::int64_t ms) {
    char text[32];
    std::snprintf(text, sizeof text, "%lld.%03llds", static_cast<long long>(ms / 1000),
                  static_cast<long long>(ms % 1000));
    return text;
}

template <class Plant, class Operand>
ScenarioReport runScenarioOn(const std::string& fileName, const BasicScenario<Operand>& scenario,
                             Plant& simulation,
                             const std::type_identity_t<std::function<void(const Plant&)>>& sample,
                             const CancelRequest& cancelled = {}) {
    using Step = BasicScenarioStep<Operand>;
    ScenarioReport report;
    if (!scenario.diagnostics.empty()) {
        for (const auto& diagnostic : scenario.diagnostics)
            report.diagnostics.push_back(lang::formatDiagnostic(fileName, diagnostic));
        report.failed = 1;
        return report;
    }
    simulation.restart();
    sample(simulation);
    // False once the caller cancels; the loops end at the scan it was asked after.
    auto scan = [&] {
        simulation.scan();
        sample(simulation);
        if (cancelled && cancelled())
            report.cancelled = true;
        return !report.cancelled;
    };
    for (const auto& step : scenario.steps) {
        if (report.cancelled)
            break;
        switch (step.kind) {
        case Step::Kind::Cycle:
            simulation.setCycleMs(static_cast<int>(step.durationMs));
            break;
        case Step::Kind::Set:
            if (step.channel)
                simulation.setChannel(step.operand, step.channel, step.value != 0);
            else
                simulation.set(step.operand, step.value);
            break;
        case Step::Kind::Release:
            simulation.release(step.operand);
            break;
        case Step::Kind::Disconnect:
        case Step::Kind::Connect:
            simulation.setOnBus(static_cast<int>(step.value), step.kind == Step::Kind::Connect);
            break;
        case Step::Kind::Run: {
            const std::int64_t end = simulation.timeMs() + step.durationMs;
            while (simulation.timeMs() < end && scan()) {
            }
            break;
        }
        case Step::Kind::Scans:
            for (std::int64_t i = 0; i < step.count && scan(); ++i) {
            }
            break;
        case Step::Kind::Expect: {
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
                                      " at t=" + scenarioSeconds(simulation.timeMs()));
            break;
        }
        }
    }
    return report;
}

} // namespace rs::sim
