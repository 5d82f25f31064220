// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Address.h"
#include "sim/Waveform.h"

#include <string>

namespace rs::pl110 {

class ScanEngine;

// A simulated PL110's waveform (sim/Waveform.h): what chosen variables did
// over virtual time, drawn by the window's waveform panel and exported as a
// VCD in the command line's form (scope "pl110").
class WaveformRecorder : public sim::BasicWaveformRecorder<Address> {
public:
    // From the next sample on, or from the engine's state now when given.
    bool add(const Address& address, const ScanEngine* engine = nullptr);
    void sample(const ScanEngine& engine);
    std::string vcd(const std::string& title) const;

    std::string label(std::size_t row) const override;
    bool isBit(std::size_t row) const override;
};

} // namespace rs::pl110
