// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// A Pluto Gateway on the project's bus (Gateway manual; ../shared/spec/
// gateway.md): the node that passes the Plutos' data to a fieldbus and, for
// GATE-E1/E2, to Modbus TCP clients.
namespace rs::project {

enum class GatewayType { E1, E2, P1, P2, D1, D2, C1, C2 };

// Gateway node addresses 0-15 (manual 3.4: DIP switch 0-3, a PLC parameter 0-15).
inline constexpr int kGatewayNodes = 16;

struct Gateway {
    GatewayType type = GatewayType::E1;

    friend bool operator==(const Gateway&, const Gateway&) = default;
};

std::string_view gatewayTypeName(GatewayType type); // "GATE-E1"
std::optional<GatewayType> gatewayTypeOfName(std::string_view name);
const std::vector<GatewayType>& gatewayTypes();
// The Ethernet gateways, which serve Modbus TCP (manual 9.4.2, Appendix D).
bool servesModbusTcp(GatewayType type);

} // namespace rs::project
