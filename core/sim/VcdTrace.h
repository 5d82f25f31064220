// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Simulation.h"
#include "VcdWriter.h"

#include <string>
#include <vector>

namespace rs::sim {

// Records chosen variables scan by scan and writes them as a Value Change
// Dump that GTKWave opens. The first sample is the state at power on (time 0);
// each later one is the state at the end of a scan, stamped with the virtual
// time at which the next scan starts. No dates or paths: the same run gives the
// same bytes.
class VcdTrace {
public:
    explicit VcdTrace(std::vector<lang::Address> variables);

    void sample(const Simulation& simulation);
    // A sample taken elsewhere (the IDE's waveform replays its recording):
    // the value of every variable, in the order given to the constructor.
    void sample(std::int64_t timeMs, const std::vector<std::int64_t>& values);
    std::string text(const std::string& title) const;

private:
    std::vector<lang::Address> m_signals;
    VcdWriter m_writer;
};

// The variables a scenario run should show: what the scenario touches and
// everything the program writes, sorted by unit and address.
std::vector<lang::Address> traceSignals(const std::vector<compiler::UnitImage>& images,
                                        const std::vector<lang::Address>& touched);

} // namespace rs::sim
