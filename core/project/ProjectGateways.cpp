// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectGateways.h"

namespace rs::project {

std::vector<int> freeGatewayNodes(const Project& project) {
    std::vector<int> nodes;
    for (int node = 0; node < kGatewayNodes; ++node)
        if (!project.gateways.count(node))
            nodes.push_back(node);
    return nodes;
}

std::optional<std::string> addGateway(Project& project, int node, GatewayType type) {
    if (node < 0 || node >= kGatewayNodes)
        return "a gateway node address is 0-" + std::to_string(kGatewayNodes - 1);
    if (project.gateways.count(node))
        return "the project already has a gateway on node " + std::to_string(node);
    Gateway gateway;
    gateway.type = type;
    project.gateways.emplace(node, gateway);
    return std::nullopt;
}

std::optional<std::string> setGateway(Project& project, int node, const Gateway& gateway) {
    auto found = project.gateways.find(node);
    if (found == project.gateways.end())
        return "the project has no gateway on node " + std::to_string(node);
    if (auto problem = gatewayProblem(gateway))
        return problem;
    found->second = gateway;
    return std::nullopt;
}

void removeGateway(Project& project, int node) {
    project.gateways.erase(node);
}

std::optional<std::string> setExternalComm(Project& project, int station,
                                           const ExternalComm& comm) {
    for (const auto& [block, setting] : comm) {
        if (block < 0 || block >= kExternalCommBlocks)
            return "External Comm Blocks are numbered 0-" + std::to_string(kExternalCommBlocks - 1);
        if (auto problem = externalCommProblem(setting))
            return "External Comm Block " + std::to_string(block) + ": " + *problem;
    }
    if (comm.empty())
        project.externalComm.erase(station);
    else
        project.externalComm[station] = comm;
    return std::nullopt;
}

ExternalComm externalCommOf(const Project& project, int station) {
    auto found = project.externalComm.find(station);
    return found == project.externalComm.end() ? ExternalComm{} : found->second;
}

} // namespace rs::project
