// SPDX-License-Identifier: GPL-3.0-or-later
#include "GatewayRecords.h"

#include <charconv>

namespace rs::project {

Annotation gatewayRecord(int node, const Gateway& gateway) {
    return {
        "gateway", {std::to_string(node)}, {{"type", std::string(gatewayTypeName(gateway.type))}}};
}

void readGatewayRecord(const Annotation& record, std::map<int, Gateway>& gateways) {
    int node = -1;
    if (record.arguments.size() == 1) {
        const std::string& word = record.arguments.front();
        const auto [end, problem] = std::from_chars(word.data(), word.data() + word.size(), node);
        if (problem != std::errc() || end != word.data() + word.size())
            node = -1;
    }
    if (node < 0 || node >= kGatewayNodes)
        throw GatewayRecordError{"@gateway needs a node address 0-" +
                                 std::to_string(kGatewayNodes - 1) +
                                 ", as in ;@gateway 0 type=\"GATE-E1\""};
    const std::string typeText = record.value("type");
    const auto type = gatewayTypeOfName(typeText);
    if (!type)
        throw GatewayRecordError{"@gateway type must be one of GATE-E1, GATE-E2, GATE-P1, "
                                 "GATE-P2, GATE-D1, GATE-D2, GATE-C1, GATE-C2, not '" +
                                 typeText + "'"};
    if (!gateways.emplace(node, Gateway{*type}).second)
        throw GatewayRecordError{"@gateway " + std::to_string(node) +
                                 ": a gateway with this node address is already declared"};
}

} // namespace rs::project
