#pragma once

#include "Scenario.h"
#include "Simulation.h"
#include "VcdTrace.h"

#include <string>
#include <vector>

namespace rs::sim {

struct ScenarioReport {
    int passed = 0;
    int failed = 0;
    std::vector<std::string> failures;    // "FILE:LINE: TEXT failed: ..."
    std::vector<std::string> diagnostics; // "FILE:LINE:COLUMN: error: ..." for syntax errors
};

// Runs one scenario from power on. A scenario with syntax errors does not run
// and counts as one failure. Every expectation counts once.
ScenarioReport runScenario(const std::string& fileName, const Scenario& scenario,
                           Simulation& simulation, VcdTrace* trace = nullptr);

// The variables a scenario sets, releases or expects.
std::vector<lang::Address> touchedBy(const Scenario& scenario);

} // namespace rs::sim
