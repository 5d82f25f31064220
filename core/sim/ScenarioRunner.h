#pragma once

#include "Scenario.h"
#include "Simulation.h"
#include "VcdTrace.h"

#include <functional>
#include <string>
#include <vector>

namespace rs::sim {

struct ScenarioReport {
    int passed = 0;
    int failed = 0;
    std::vector<std::string> failures;    // "FILE:LINE: TEXT failed: ..."
    std::vector<int> failureLines;        // the scenario line of each failure, in the same order
    std::vector<std::string> diagnostics; // "FILE:LINE:COLUMN: error: ..." for syntax errors
};

// Called with the simulation at power on and after every scan of a run, as
// the trace samples it (the IDE's waveform records the run this way).
using ScanObserver = std::function<void(const Simulation&)>;

// Runs one scenario from power on. A scenario with syntax errors does not run
// and counts as one failure. Every expectation counts once.
ScenarioReport runScenario(const std::string& fileName, const Scenario& scenario,
                           Simulation& simulation, VcdTrace* trace = nullptr,
                           const ScanObserver& observer = {});

// The variables a scenario sets, releases or expects.
std::vector<lang::Address> touchedBy(const Scenario& scenario);

} // namespace rs::sim
