// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Program.h"
#include "ScanEngine.h"
#include "sim/Scenario.h"
#include "sim/ScenarioRunner.h"
#include "sim/VcdWriter.h"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

// Scenarios (../shared/spec/scenario.md) for a PL110 program: the same file
// format and runner as Pluto's, with the PL110's addresses and names
// (docs/pl110.md, "Scenarios").
namespace rs::pl110 {

using Scenario = sim::BasicScenario<Address>;

// The scenario reader's vocabulary: addresses as the text form writes them
// and the program's declared names, case-insensitive. A timer's or
// counter's number is its contact. A PL110 has no bus: connect and
// disconnect name no unit.
class ScenarioNames {
public:
    using Operand = Address;

    explicit ScenarioNames(const Program& program);
    bool resolve(std::string_view word, Address& address, std::string& error) const;
    bool resolveChannel(std::string_view word, Address& address, int& channel,
                        std::string& error) const;
    bool hasStation(int) const { return false; }
    sim::ValueRange range(const Address& address) const;
    std::string spelling(const Address& address) const { return toString(address); }

private:
    std::vector<std::pair<std::string, Address>> m_names; // upper-case name -> address
};

Scenario parseScenario(std::string_view text, const ScenarioNames& names);

// Runs one scenario from power on; `sample` sees the engine at power on and
// after every scan; `cancelled` is asked after every scan (a server's stop).
sim::ScenarioReport runScenario(const std::string& fileName, const Scenario& scenario,
                                ScanEngine& engine,
                                const std::function<void(const ScanEngine&)>& sample = {},
                                const sim::CancelRequest& cancelled = {});

// The variables a scenario sets, releases or expects.
std::vector<Address> touchedBy(const Scenario& scenario);

// What a scenario run's trace shows: what the scenario touches and
// everything the program writes (coils, bits, timers' and counters'
// contacts and values, MOV and FM targets), in address order.
std::vector<Address> traceSignals(const Program& program, const std::vector<Address>& touched);
// As a VCD shows them: one scope, "pl110", named as the text form writes
// them with '_' for '.'.
std::vector<sim::VcdSignal> vcdSignals(const std::vector<Address>& variables);

} // namespace rs::pl110
