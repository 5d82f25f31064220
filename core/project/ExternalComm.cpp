// SPDX-License-Identifier: GPL-3.0-or-later
#include "ExternalComm.h"

#include "Gateway.h"
#include "RecordWords.h"

namespace rs::project {

namespace {

int extCommNumber(const Annotation& record, std::string_view key, int fallback) {
    const std::string text = record.value(key);
    if (text.empty())
        return fallback;
    const auto value = wholeNumber(text);
    if (!value)
        throw ExternalCommRecordError{"@ext_comm " + std::string(key) + " must be a number, not '" +
                                      text + "'"};
    return *value;
}

} // namespace

std::optional<std::string> externalCommProblem(const ExternalCommBlock& block) {
    if (block.gateway < 0 || block.gateway >= kGatewayNodes)
        return "the gateway node address must be 0-" + std::to_string(kGatewayNodes - 1);
    if (block.packet < 0 || block.packet >= kToPlutoPackets)
        return "the packet must be 0-" + std::to_string(kToPlutoPackets - 1);
    if (block.timeoutMs < 0 || block.timeoutMs > kMaxExternalTimeoutMs)
        return "the timeout must be 0 (none) to " + std::to_string(kMaxExternalTimeoutMs) + " ms";
    return std::nullopt;
}

std::vector<Annotation> externalCommRecords(int station, const ExternalComm& comm) {
    std::vector<Annotation> records;
    for (const auto& [number, block] : comm) {
        Annotation record{
            "ext_comm",
            {stationText(station), std::to_string(number)},
            {{"gateway", std::to_string(block.gateway)}, {"packet", std::to_string(block.packet)}}};
        if (block.timeoutMs != kDefaultExternalTimeoutMs)
            record.attributes.emplace_back("timeout_ms", std::to_string(block.timeoutMs));
        records.push_back(std::move(record));
    }
    return records;
}

void readExternalCommRecord(const Annotation& record, std::map<int, ExternalComm>& units) {
    const auto station =
        record.arguments.size() == 2 ? wholeNumber(record.arguments[0]) : std::optional<int>();
    const auto block =
        record.arguments.size() == 2 ? wholeNumber(record.arguments[1]) : std::optional<int>();
    if (!station || *station < 0 || *station > 31 || !block || *block < 0 ||
        *block >= kExternalCommBlocks)
        throw ExternalCommRecordError{"@ext_comm needs a station 0-31 and an External Comm "
                                      "Block 0-3, as in ;@ext_comm 01 0 gateway=\"0\" "
                                      "packet=\"0\""};
    ExternalCommBlock setting{extCommNumber(record, "gateway", -1),
                              extCommNumber(record, "packet", -1),
                              extCommNumber(record, "timeout_ms", kDefaultExternalTimeoutMs)};
    if (auto problem = externalCommProblem(setting))
        throw ExternalCommRecordError{"@ext_comm " + stationText(*station) + " " +
                                      std::to_string(*block) + ": " + *problem};
    if (!units[*station].emplace(*block, setting).second)
        throw ExternalCommRecordError{"@ext_comm " + stationText(*station) + " " +
                                      std::to_string(*block) + " is already given"};
}

} // namespace rs::project
