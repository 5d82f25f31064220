// SPDX-License-Identifier: GPL-3.0-or-later
#include "WaveformRecorder.h"

#include "ScanEngine.h"
#include "Scenario.h"
#include "sim/VcdWriter.h"

namespace rs::pl110 {

bool WaveformRecorder::add(const Address& address, const ScanEngine* engine) {
    return BasicWaveformRecorder::add(address, engine ? std::optional(engine->value(address))
                                                      : std::nullopt);
}

void WaveformRecorder::sample(const ScanEngine& engine) {
    BasicWaveformRecorder::sample(
        engine.timeMs(), [&engine](const Address& address) { return engine.value(address); });
}

std::string WaveformRecorder::vcd(const std::string& title) const {
    sim::VcdWriter out(vcdSignals(sortedAddresses()));
    replay([&out](std::int64_t timeMs, const std::vector<std::int64_t>& values) {
        out.sample(timeMs, values);
    });
    return out.text(title);
}

std::string WaveformRecorder::label(std::size_t row) const {
    return toString(traces()[row].address);
}

bool WaveformRecorder::isBit(std::size_t row) const {
    return traces()[row].address.width == Width::Bit;
}

} // namespace rs::pl110
