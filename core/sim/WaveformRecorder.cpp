// SPDX-License-Identifier: GPL-3.0-or-later
#include "WaveformRecorder.h"

#include "Simulation.h"
#include "VcdTrace.h"

#include <algorithm>
#include <set>

namespace rs::sim {

bool WaveformRecorder::add(const lang::Address& address, const Simulation* simulation) {
    if (contains(address))
        return false;
    m_traces.push_back({address, {}});
    if (simulation && m_sampled)
        m_traces.back().changes.push_back({m_endMs, simulation->value(address)});
    return true;
}

void WaveformRecorder::remove(const lang::Address& address) {
    std::erase_if(m_traces, [&](const Trace& trace) { return trace.address == address; });
}

void WaveformRecorder::removeAll() {
    m_traces.clear();
}

bool WaveformRecorder::contains(const lang::Address& address) const {
    return std::any_of(m_traces.begin(), m_traces.end(),
                       [&](const Trace& trace) { return trace.address == address; });
}

void WaveformRecorder::clear() {
    for (Trace& trace : m_traces)
        trace.changes.clear();
    m_sampled = false;
    m_startMs = m_endMs = 0;
}

void WaveformRecorder::sample(const Simulation& simulation) {
    const std::int64_t now = simulation.timeMs();
    if (!m_sampled) {
        m_startMs = now;
        m_sampled = true;
    }
    m_endMs = now;
    for (Trace& trace : m_traces) {
        const std::int64_t value = simulation.value(trace.address);
        if (trace.changes.empty() || trace.changes.back().value != value)
            trace.changes.push_back({now, value});
    }
}

std::string WaveformRecorder::vcd(const std::string& title) const {
    std::vector<const Trace*> sorted;
    for (const Trace& trace : m_traces)
        sorted.push_back(&trace);
    std::sort(sorted.begin(), sorted.end(),
              [](const Trace* a, const Trace* b) { return a->address < b->address; });
    std::vector<lang::Address> addresses;
    std::set<std::int64_t> times;
    for (const Trace* trace : sorted) {
        addresses.push_back(trace->address);
        for (const Change& change : trace->changes)
            times.insert(change.timeMs);
    }
    VcdTrace out(addresses);
    // Replays the changes in time order; a variable added during the run has
    // its first recorded value before that.
    std::vector<std::size_t> next(sorted.size(), 0);
    std::vector<std::int64_t> values(sorted.size(), 0);
    for (std::size_t i = 0; i < sorted.size(); ++i)
        if (!sorted[i]->changes.empty())
            values[i] = sorted[i]->changes.front().value;
    for (std::int64_t time : times) {
        for (std::size_t i = 0; i < sorted.size(); ++i) {
            const auto& changes = sorted[i]->changes;
            while (next[i] < changes.size() && changes[next[i]].timeMs <= time)
                values[i] = changes[next[i]++].value;
        }
        out.sample(time, values);
    }
    return out.text(title);
}

} // namespace rs::sim
