// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Waveform.h"
#include "lang/Address.h"

#include <cstdint>
#include <string>

namespace rs::sim {

class Simulation;

// A Pluto simulation's waveform: what chosen variables did over virtual
// time (Waveform.h); the IDE's waveform panel draws it and exports it as VCD.
class WaveformRecorder : public BasicWaveformRecorder<lang::Address> {
public:
    // Records the variable from the next sample on, or from the last one
    // when the simulation is given; false when it is recorded already.
    bool add(const lang::Address& address, const Simulation* simulation = nullptr);
    void sample(const Simulation& simulation);
    // A Value Change Dump of the traces (core VcdTrace), variables in address order.
    std::string vcd(const std::string& title) const;

    std::string label(std::size_t row) const override;
    bool isBit(std::size_t row) const override;
};

} // namespace rs::sim
