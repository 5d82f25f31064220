// SPDX-License-Identifier: GPL-3.0-or-later
#include "WaveformRecorder.h"

#include "Simulation.h"
#include "VcdTrace.h"

#include <algorithm>
#include <set>

namespace rs::sim {

bool WaveformRecorder::add(const lang::Address& address, const Simulation* simulation) {
    return BasicWaveformRecorder::add(
        address, simulation ? std::optional(simulation->value(address)) : std::nullopt);
}

void WaveformRecorder::sample(const Simulation& simulation) {
    BasicWaveformRecorder::sample(simulation.timeMs(), [&simulation](const lang::Address& address) {
        return simulation.value(address);
    });
}

std::string WaveformRecorder::label(std::size_t row) const {
    return lang::toString(traces()[row].address);
}

bool WaveformRecorder::isBit(std::size_t row) const {
    const lang::Address& address = traces()[row].address;
    return address.isBit() && address.kind != lang::AddressKind::AnalogInput;
}

std::string WaveformRecorder::vcd(const std::string& title) const {
    std::vector<const Trace*> sorted;
    for (const Trace& trace : traces())
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
