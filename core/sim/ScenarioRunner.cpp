// SPDX-License-Identifier: GPL-3.0-or-later
#include "ScenarioRunner.h"

#include "ScenarioRun.h"

#include <algorithm>
#include <limits>

namespace rs::sim {

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
    return runScenarioOn(
        fileName, scenario, simulation,
        [&](const Simulation& now) {
            if (trace)
                trace->sample(now);
            if (observer)
                observer(now);
        },
        cancelled);
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
