// SPDX-License-Identifier: GPL-3.0-or-later
#include "GatewayRecords.h"

#include "RecordWords.h"

namespace rs::project {

namespace {

// "0-3,5": numbers and runs, comma separated; nothing when malformed.
std::optional<std::set<int>> numberList(std::string_view text) {
    std::set<int> numbers;
    while (!text.empty()) {
        const auto comma = text.find(',');
        const std::string_view item = text.substr(0, comma);
        text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
        const auto dash = item.find('-');
        const auto first = wholeNumber(item.substr(0, dash));
        const auto last =
            dash == std::string_view::npos ? first : wholeNumber(item.substr(dash + 1));
        if (!first || !last || *last < *first || *last - *first > 31)
            return std::nullopt;
        for (int n = *first; n <= *last; ++n)
            numbers.insert(n);
    }
    return numbers;
}

std::string listText(const std::set<int>& numbers) {
    std::string text;
    for (auto it = numbers.begin(); it != numbers.end();) {
        int last = *it;
        auto next = std::next(it);
        while (next != numbers.end() && *next == last + 1)
            last = *next++;
        text += (text.empty() ? "" : ",") + std::to_string(*it) +
                (last > *it ? "-" + std::to_string(last) : std::string());
        it = next;
    }
    return text;
}

GatewayRecordError formError(const Annotation& record) {
    return {"@" + record.kind + " needs a node address 0-" + std::to_string(kGatewayNodes - 1) +
            (record.kind == "gateway" ? ", as in ;@gateway 0 type=\"GATE-E1\""
                                      : " and an area 0-31, as in ;@gateway_area 0 5 pluto=\"2\" "
                                        "io_type=\"101\"")};
}

int nodeOf(const Annotation& record, std::size_t arguments) {
    const auto node =
        record.arguments.size() == arguments ? wholeNumber(record.arguments.front()) : std::nullopt;
    if (!node || *node < 0 || *node >= kGatewayNodes)
        throw formError(record);
    return *node;
}

int numberAttribute(const Annotation& record, std::string_view key, int fallback) {
    const std::string text = record.value(key);
    if (text.empty())
        return fallback;
    const auto value = wholeNumber(text);
    if (!value)
        throw GatewayRecordError{"@" + record.kind + " " + std::string(key) +
                                 " must be a number, not '" + text + "'"};
    return *value;
}

std::set<int> listAttribute(const Annotation& record, std::string_view key) {
    const std::string text = record.value(key);
    if (text.empty())
        return {};
    const auto list = numberList(text);
    if (!list)
        throw GatewayRecordError{"@gateway " + std::string(key) +
                                 " must be numbers and runs such as 0-3,5, not '" + text + "'"};
    return *list;
}

void check(const Annotation& record, int node, const Gateway& gateway) {
    if (auto problem = gatewayProblem(gateway))
        throw GatewayRecordError{"@" + record.kind + " " + std::to_string(node) + ": " + *problem};
}

} // namespace

std::vector<Annotation> gatewayRecords(int node, const Gateway& gateway) {
    Annotation head{"gateway", {std::to_string(node)}, {}};
    head.attributes.emplace_back("type", std::string(gatewayTypeName(gateway.type)));
    if (gateway.cycleMs != kDefaultGatewayCycleMs)
        head.attributes.emplace_back("cycle_ms", std::to_string(gateway.cycleMs));
    if (gateway.timeoutMs != 0)
        head.attributes.emplace_back("timeout_ms", std::to_string(gateway.timeoutMs));
    if (!gateway.toPluto.empty())
        head.attributes.emplace_back("to_pluto", listText(gateway.toPluto));
    if (!gateway.expectedNodes.empty())
        head.attributes.emplace_back("expected", listText(gateway.expectedNodes));
    std::vector<Annotation> records{head};
    for (const auto& [area, data] : gateway.areas)
        records.push_back(
            {"gateway_area",
             {std::to_string(node), std::to_string(area)},
             {{"pluto", std::to_string(data.pluto)}, {"io_type", std::to_string(data.ioType)}}});
    return records;
}

void readGatewayRecord(const Annotation& record, std::map<int, Gateway>& gateways) {
    if (record.kind == "gateway_area") {
        const int node = nodeOf(record, 2);
        const auto area = wholeNumber(record.arguments[1]);
        if (!area || *area < 0 || *area >= kGatewayAreas)
            throw formError(record);
        auto gateway = gateways.find(node);
        if (gateway == gateways.end())
            throw GatewayRecordError{"@gateway_area " + std::to_string(node) +
                                     ": no gateway with this node address is declared before it"};
        Gateway changed = gateway->second;
        if (!changed.areas
                 .emplace(*area, GatewayArea{numberAttribute(record, "pluto", -1),
                                             numberAttribute(record, "io_type", 0)})
                 .second)
            throw GatewayRecordError{"@gateway_area " + std::to_string(node) + " " +
                                     std::to_string(*area) + " is already given"};
        check(record, node, changed);
        gateway->second = std::move(changed);
        return;
    }
    const int node = nodeOf(record, 1);
    const std::string typeText = record.value("type");
    const auto type = gatewayTypeOfName(typeText);
    if (!type)
        throw GatewayRecordError{"@gateway type must be one of GATE-E1, GATE-E2, GATE-P1, "
                                 "GATE-P2, GATE-D1, GATE-D2, GATE-C1, GATE-C2, not '" +
                                 typeText + "'"};
    Gateway gateway;
    gateway.type = *type;
    gateway.cycleMs = numberAttribute(record, "cycle_ms", kDefaultGatewayCycleMs);
    gateway.timeoutMs = numberAttribute(record, "timeout_ms", 0);
    gateway.toPluto = listAttribute(record, "to_pluto");
    gateway.expectedNodes = listAttribute(record, "expected");
    check(record, node, gateway);
    if (!gateways.emplace(node, gateway).second)
        throw GatewayRecordError{"@gateway " + std::to_string(node) +
                                 ": a gateway with this node address is already declared"};
}

} // namespace rs::project
