// SPDX-License-Identifier: GPL-3.0-or-later
#include "WaveformRecorder.h"

#include "Simulation.h"
#include "VcdTrace.h"

#include <algorithm>

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
    VcdTrace out(sortedAddresses());
    replay([&out](std::int64_t timeMs, const std::vector<std::int64_t>& values) {
        out.sample(timeMs, values);
    });
    return out.text(title);
}

} // namespace rs::sim
