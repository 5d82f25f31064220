// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <map>
#include <optional>
#include <set>
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

// An Additional Data area (manual 4.3): which Pluto sends it and what:
// IO-type 1-99 a user block's number, 100-113 a standard block's data.
struct GatewayArea {
    int pluto = 0;
    int ioType = 0;

    friend bool operator==(const GatewayArea&, const GatewayArea&) = default;
};

// Limits the manual gives (4.3, 4.4; ../shared/research/gateway.md).
inline constexpr int kGatewayAreas = 32;
inline constexpr int kToPlutoPackets = 4;
inline constexpr int kMinGatewayCycleMs = 4;
inline constexpr int kMaxGatewayCycleMs = 255;
inline constexpr int kDefaultGatewayCycleMs = 100;
inline constexpr int kMaxGatewayTimeoutMs = 60'000;
inline constexpr int kMinEthernetTimeoutMs = 1000; // GATE-E1/E2: 0 or 1000-60000
inline constexpr int kMinIoType = 1;
inline constexpr int kMaxIoType = 113;

struct Gateway {
    GatewayType type = GatewayType::E1;
    std::map<int, GatewayArea> areas;     // Additional Data 0-31 in use
    std::set<int> toPluto;                // Data to Pluto packets 0-3 enabled
    int cycleMs = kDefaultGatewayCycleMs; // Data to Pluto is sent this often
    int timeoutMs = 0;                    // Data to Pluto: 0 no timeout
    std::set<int> expectedNodes;          // Plutos 0-31 the gateway expects

    friend bool operator==(const Gateway&, const Gateway&) = default;
};

// What is wrong with the gateway's settings by the manual's ranges; nothing
// when they are sound.
std::optional<std::string> gatewayProblem(const Gateway& gateway);

std::string_view gatewayTypeName(GatewayType type); // "GATE-E1"
std::optional<GatewayType> gatewayTypeOfName(std::string_view name);
const std::vector<GatewayType>& gatewayTypes();
// The Ethernet gateways, which serve Modbus TCP (manual 9.4.2, Appendix D).
bool servesModbusTcp(GatewayType type);

} // namespace rs::project
