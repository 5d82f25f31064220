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

} // namespace rs::project
