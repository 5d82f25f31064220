// SPDX-License-Identifier: GPL-3.0-or-later
#include "GatewayConfiguration.h"

namespace rs::gateway {

namespace {

constexpr int kEnable = 1;
constexpr int kTimeout = 2;
constexpr int kExpectedHigh = 3;
constexpr int kExpectedLow = 4;
constexpr int kFirstArea = 5;
constexpr int kCycle = 37;
constexpr int kProfinetLast = 40;

std::uint32_t expectedBitmap(const project::Gateway& settings) {
    std::uint32_t bits = 0;
    for (int node : settings.expectedNodes)
        bits |= 1u << node;
    return bits;
}

} // namespace

ModbusException writeConfiguration(project::Gateway& settings, int node, int address,
                                   const std::vector<std::uint16_t>& values) {
    project::Gateway changed = settings;
    std::uint32_t expected = expectedBitmap(settings);
    for (std::size_t i = 0; i < values.size(); ++i) {
        const int at = address + static_cast<int>(i);
        const std::uint16_t value = values[i];
        if (at == 0) {
            if (value != kConfigurationLength && value != kConfigurationLast)
                return ModbusException::IllegalDataValue;
        } else if (at == kEnable) {
            if (value > 0xF)
                return ModbusException::IllegalDataValue;
            changed.toPluto.clear();
            for (int packet = 0; packet < project::kToPlutoPackets; ++packet)
                if (value & (1u << packet))
                    changed.toPluto.insert(packet);
        } else if (at == kTimeout) {
            changed.timeoutMs = value;
        } else if (at == kExpectedHigh) {
            expected = (expected & 0xFFFFu) | std::uint32_t{value} << 16;
        } else if (at == kExpectedLow) {
            expected = (expected & 0xFFFF0000u) | value;
        } else if (at >= kFirstArea && at < kFirstArea + project::kGatewayAreas) {
            const int pluto = value >> 8;
            const int ioType = value & 0xFF;
            if (ioType == 0)
                changed.areas.erase(at - kFirstArea);
            else
                changed.areas[at - kFirstArea] = {pluto, ioType};
        } else if (at == kCycle) {
            changed.cycleMs = value;
        } else if (at <= kProfinetLast) {
            // PROFINET settings: nothing of a simulated Ethernet gateway.
        } else if (at == kConfigurationLast) {
            if (value != node)
                return ModbusException::IllegalDataValue;
        }
    }
    changed.expectedNodes.clear();
    for (int n = 0; n < 32; ++n)
        if (expected & (1u << n))
            changed.expectedNodes.insert(n);
    if (project::gatewayProblem(changed))
        return ModbusException::IllegalDataValue;
    settings = std::move(changed);
    return ModbusException::None;
}

} // namespace rs::gateway
