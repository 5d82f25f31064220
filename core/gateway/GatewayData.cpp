// SPDX-License-Identifier: GPL-3.0-or-later
#include "GatewayData.h"

namespace rs::gateway {

namespace {

using target::UnitType;

// Bits first..first+count-1 of the value from `bit(i)`, i counting from 0.
template <typename Bit> std::uint32_t bits(int first, int count, Bit bit) {
    std::uint32_t value = 0;
    for (int i = 0; i < count; ++i)
        if (bit(i))
            value |= 1u << (first + i);
    return value;
}

// Bytes 2 and 3 of the A20, Double and AS-i families: Q0-Q3, GM0-GM11.
std::uint32_t outputsAndGlobalMemories(const sim::UnitMemory& m, bool hasSafetyOutputs) {
    return bits(16, 4, [&](int i) { return hasSafetyOutputs && m.outputs[i] != 0; }) |
           bits(20, 12, [&](int i) { return m.globalMemories[i] != 0; });
}

} // namespace

std::uint32_t nodeStatus(const sim::Simulation& simulation) {
    std::uint32_t status = 0;
    for (int station : simulation.stations())
        if (station >= 0 && station < 32 && simulation.isOnBus(station))
            status |= 1u << station;
    return status;
}

std::uint32_t globalData(UnitType type, const sim::UnitMemory& m) {
    const auto input = [&](int number) {
        return m.inputs[static_cast<std::size_t>(number)] != 0;
    };
    const auto analog = [&](int i) {
        return m.analogInputs[static_cast<std::size_t>(i)] != 0;
    };
    switch (type) {
    case UnitType::ASi:
        // I.0 and the safety slaves ASi.1-ASi.15 (manual 4.2, "Pluto AS-i family").
        return bits(0, 1, [&](int) { return input(0); }) |
               bits(1, 15,
                    [&](int i) { return m.asiSafeInputs[static_cast<std::size_t>(i + 1)] != 0; }) |
               outputsAndGlobalMemories(m, true);
    case UnitType::B42ASi:
        // I.0-I.3 and GM0-GM27; no global safety outputs.
        return bits(0, 4, input) | bits(4, 28, [&](int i) {
                   return m.globalMemories[static_cast<std::size_t>(i)] != 0;
               });
    case UnitType::D20:
        // IA0-IA3 stand where I0-I3 stand on the others (read as bits: not 0).
        return bits(0, 4, analog) | bits(4, 4, [&](int i) { return input(4 + i); }) |
               bits(8, 8, [&](int i) { return input(10 + i); }) | outputsAndGlobalMemories(m, true);
    case UnitType::D45:
        return bits(0, 8, analog) | bits(8, 8, [&](int i) { return input(10 + i); }) |
               outputsAndGlobalMemories(m, true);
    default:
        // The A20 and Double families; a B22 has no global safety outputs.
        return bits(0, 8, input) | bits(8, 8, [&](int i) { return input(10 + i); }) |
               outputsAndGlobalMemories(m, type != UnitType::B22);
    }
}

std::uint32_t globalData(const sim::Simulation& simulation, int station) {
    const sim::UnitEngine* unit = simulation.unit(station);
    const auto type = unit ? static_cast<UnitType>(unit->image().unitType) : UnitType::A20;
    return globalData(type, simulation.published(station));
}

} // namespace rs::gateway
