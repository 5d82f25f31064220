// SPDX-License-Identifier: GPL-3.0-or-later
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
    bool cancelled = false;               // stopped early at the caller's request
};

// Called with the simulation at power on and after every scan of a run, as
// the trace samples it (the IDE's waveform records the run this way).
using ScanObserver = std::function<void(const Simulation&)>;
// Asked after every scan; true stops the run there (a GUI's Cancel).
using CancelRequest = std::function<bool()>;

// Runs one scenario from power on. A scenario with syntax errors does not run
// and counts as one failure. Every expectation counts once.
ScenarioReport runScenario(const std::string& fileName, const Scenario& scenario,
                           Simulation& simulation, VcdTrace* trace = nullptr,
                           const ScanObserver& observer = {}, const CancelRequest& cancelled = {});

// The virtual time the scenario runs at most, from power on at the given
// cycle: what a progress figure counts towards.
std::int64_t scenarioLengthMs(const Scenario& scenario, int cycleMs);

// The variables a scenario sets, releases or expects.
std::vector<lang::Address> touchedBy(const Scenario& scenario);

} // namespace rs::sim
