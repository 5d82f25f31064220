// SPDX-License-Identifier: GPL-3.0-or-later
#include "Gateway.h"

#include <algorithm>
#include <array>
#include <utility>

namespace rs::project {

namespace {

constexpr std::array<std::pair<GatewayType, std::string_view>, 8> kNames{{
    {GatewayType::E1, "GATE-E1"},
    {GatewayType::E2, "GATE-E2"},
    {GatewayType::P1, "GATE-P1"},
    {GatewayType::P2, "GATE-P2"},
    {GatewayType::D1, "GATE-D1"},
    {GatewayType::D2, "GATE-D2"},
    {GatewayType::C1, "GATE-C1"},
    {GatewayType::C2, "GATE-C2"},
}};

} // namespace

std::string_view gatewayTypeName(GatewayType type) {
    for (const auto& [t, name] : kNames)
        if (t == type)
            return name;
    return {};
}

std::optional<GatewayType> gatewayTypeOfName(std::string_view name) {
    for (const auto& [type, text] : kNames)
        if (std::equal(text.begin(), text.end(), name.begin(), name.end(),
                       [](char a, char b) { return a == (b >= 'a' && b <= 'z' ? b - 32 : b); }))
            return type;
    return std::nullopt;
}

const std::vector<GatewayType>& gatewayTypes() {
    static const std::vector<GatewayType> types = [] {
        std::vector<GatewayType> all;
        for (const auto& [type, name] : kNames)
            all.push_back(type);
        return all;
    }();
    return types;
}

bool servesModbusTcp(GatewayType type) {
    return type == GatewayType::E1 || type == GatewayType::E2;
}

std::optional<std::string> gatewayProblem(const Gateway& gateway) {
    for (const auto& [area, data] : gateway.areas) {
        const std::string where = "additional data area " + std::to_string(area);
        if (area < 0 || area >= kGatewayAreas)
            return "additional data areas are numbered 0-" + std::to_string(kGatewayAreas - 1);
        if (data.pluto < 0 || data.pluto > 31)
            return where + ": a Pluto is numbered 0-31";
        if (data.ioType < kMinIoType || data.ioType > kMaxIoType)
            return where + ": the IO-type is 1-99 for a user block, 100-113 for a standard one";
    }
    for (int packet : gateway.toPluto)
        if (packet < 0 || packet >= kToPlutoPackets)
            return "Data to Pluto packets are numbered 0-" + std::to_string(kToPlutoPackets - 1);
    for (int node : gateway.expectedNodes)
        if (node < 0 || node > 31)
            return "an expected node is a Pluto 0-31";
    if (gateway.cycleMs < kMinGatewayCycleMs || gateway.cycleMs > kMaxGatewayCycleMs)
        return "the cycle time is " + std::to_string(kMinGatewayCycleMs) + "-" +
               std::to_string(kMaxGatewayCycleMs) + " ms";
    const int least = servesModbusTcp(gateway.type) ? kMinEthernetTimeoutMs : 1;
    if (gateway.timeoutMs != 0 &&
        (gateway.timeoutMs < least || gateway.timeoutMs > kMaxGatewayTimeoutMs))
        return "the timeout is 0 (none) or " + std::to_string(least) + "-" +
               std::to_string(kMaxGatewayTimeoutMs) + " ms" +
               (least > 1 ? std::string(" on an Ethernet gateway") : std::string());
    return std::nullopt;
}

} // namespace rs::project
