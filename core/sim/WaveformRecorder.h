// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Address.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rs::sim {

class Simulation;

// What chosen variables did over virtual time, scan by scan, kept as their
// changes only: the IDE's waveform panel draws it and exports it as VCD. A sample
// is stamped as the VCD trace of a scenario stamps it: power on at its time,
// each scan's results at the time the next scan starts.
class WaveformRecorder {
public:
    struct Change {
        std::int64_t timeMs = 0;
        std::int64_t value = 0;
    };
    struct Trace {
        lang::Address address;
        std::vector<Change> changes; // the first is the value when recording began
    };

    // Records the variable from the next sample on, or from the last one when
    // the simulation is given; false when it is recorded already.
    bool add(const lang::Address& address, const Simulation* simulation = nullptr);
    void remove(const lang::Address& address);
    // Stops recording every variable: a large run's traces cost time each scan.
    void removeAll();
    bool contains(const lang::Address& address) const;
    // Forgets what was recorded (power on again, a new run) but keeps the variables.
    void clear();

    void sample(const Simulation& simulation);

    const std::vector<Trace>& traces() const { return m_traces; }
    // The time of the first and the last sample; equal when nothing was recorded.
    std::int64_t startMs() const { return m_startMs; }
    std::int64_t endMs() const { return m_endMs; }
    bool isEmpty() const { return !m_sampled; }

    // A Value Change Dump of the traces (core VcdTrace), variables in address order.
    std::string vcd(const std::string& title) const;

private:
    std::vector<Trace> m_traces;
    std::int64_t m_startMs = 0;
    std::int64_t m_endMs = 0;
    bool m_sampled = false;
};

} // namespace rs::sim
