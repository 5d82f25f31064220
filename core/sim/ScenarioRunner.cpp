#include "ScenarioRunner.h"

#include <cstdio>

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
                           Simulation& simulation, VcdTrace* trace, const ScanObserver& observer) {
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
    auto scan = [&] {
        simulation.scan();
        sample();
    };
    for (const auto& step : scenario.steps) {
        switch (step.kind) {
        case ScenarioStep::Kind::Cycle:
            simulation.setCycleMs(static_cast<int>(step.durationMs));
            break;
        case ScenarioStep::Kind::Set:
            simulation.set(step.operand, step.value);
            break;
        case ScenarioStep::Kind::Release:
            simulation.release(step.operand);
            break;
        case ScenarioStep::Kind::Run: {
            const std::int64_t end = simulation.timeMs() + step.durationMs;
            while (simulation.timeMs() < end)
                scan();
            break;
        }
        case ScenarioStep::Kind::Scans:
            for (std::int64_t i = 0; i < step.count; ++i)
                scan();
            break;
        case ScenarioStep::Kind::Expect: {
            const std::int64_t deadline = simulation.timeMs() + step.durationMs;
            bool held = simulation.value(step.operand) == step.value;
            while (!held && simulation.timeMs() < deadline) {
                scan();
                held = simulation.value(step.operand) == step.value;
            }
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

} // namespace rs::sim
