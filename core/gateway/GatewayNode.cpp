// SPDX-License-Identifier: GPL-3.0-or-later
#include "GatewayNode.h"

#include "GatewayConfiguration.h"

#include <algorithm>

namespace rs::gateway {

namespace {

constexpr int kAdditionalDataFirst = 67;
constexpr int kValidBits = 1; // unit 1: the areas' valid bits

} // namespace

GatewayNode::GatewayNode(int node, project::Gateway settings)
    : m_node(node), m_settings(std::move(settings)) {}

std::uint32_t GatewayNode::additionalData(int area) const {
    return area >= 0 && area < project::kGatewayAreas ? m_areas[static_cast<std::size_t>(area)] : 0;
}

void GatewayNode::takeTelegrams(const sim::Simulation& simulation) {
    const std::int64_t now = simulation.timeMs();
    for (const int station : simulation.stations()) {
        if (!simulation.isOnBus(station))
            continue;
        for (const auto& telegram : simulation.unit(station)->telegrams())
            for (const auto& [area, source] : m_settings.areas)
                if (source.pluto == station && source.ioType == telegram.ioType) {
                    m_areas[static_cast<std::size_t>(area)] = telegram.data;
                    m_areaReceivedMs[static_cast<std::size_t>(area)] = now;
                    break; // "only the first allocated Additional Data Area"
                }
    }
    for (int area = 0; area < project::kGatewayAreas; ++area) {
        const auto a = static_cast<std::size_t>(area);
        if (!m_settings.areas.count(area) || now - m_areaReceivedMs[a] > kAdditionalDataTimeoutMs)
            m_areas[a] = 0;
    }
}

void GatewayNode::sendToPluto(sim::Simulation& simulation) {
    const std::int64_t now = simulation.timeMs();
    if (m_written) {
        m_written = false;
        m_hasData = true;
        m_writtenMs = now;
    }
    // "the data will be cleared and the gateway will transmit 0" (4.4.3)
    if (m_hasData && m_settings.timeoutMs > 0 && now - m_writtenMs > m_settings.timeoutMs) {
        m_hasData = false;
        std::fill(m_toPluto.begin() + kValidBits, m_toPluto.end(), std::uint16_t{0});
    }
    if (now < m_nextCycleMs)
        return;
    m_nextCycleMs = now + m_settings.cycleMs;
    for (const int packet : m_settings.toPluto) {
        const auto at = static_cast<std::size_t>(kValidBits + 1 + 3 * packet);
        sim::Simulation::Packet data;
        data.valid = (m_toPluto[kValidBits] >> packet) & 1u;
        data.bits = m_toPluto[at];
        data.register0 = static_cast<std::int16_t>(m_toPluto[at + 1]);
        data.register1 = static_cast<std::int16_t>(m_toPluto[at + 2]);
        simulation.deliverPacket(m_node, packet, data);
    }
}

void GatewayNode::exchange(sim::Simulation& simulation) {
    takeTelegrams(simulation);
    sendToPluto(simulation);
    serveLocalData(m_localData, simulation);
    m_fromPluto = gateway::dataFromPluto(simulation);
    for (int area = 0; area < project::kGatewayAreas; ++area) {
        const std::uint32_t value = m_areas[static_cast<std::size_t>(area)];
        const auto at = static_cast<std::size_t>(kAdditionalDataFirst + 2 * area);
        m_fromPluto[at] = static_cast<std::uint16_t>(value >> 16);
        m_fromPluto[at + 1] = static_cast<std::uint16_t>(value & 0xFFFFu);
    }
}

ModbusResponse GatewayNode::answer(const ModbusRequest& request) {
    switch (request.unit) {
    case kConfigurationUnit: {
        if (request.function != kWriteMultipleRegisters)
            return {ModbusException::IllegalFunction, {}}; // unit 4 is write only
        if (request.count < 1 || request.count > kMaxRegistersPerRequest ||
            request.values.size() != static_cast<std::size_t>(request.count))
            return {ModbusException::IllegalDataValue, {}};
        if (request.address < 0 || request.address + request.count - 1 > kConfigurationLast)
            return {ModbusException::IllegalDataAddress, {}};
        return {writeConfiguration(m_settings, m_node, request.address, request.values), {}};
    }
    case kLocalDataRequestUnit:
    case kLocalDataResponseUnit:
        return answerLocalData(request, m_localData);
    default: {
        ModbusResponse response = gateway::answer(request, m_fromPluto, m_toPluto);
        if (request.unit == kDataToPlutoUnit && request.function == kWriteMultipleRegisters &&
            response.exception == ModbusException::None)
            m_written = true;
        return response;
    }
    }
}

} // namespace rs::gateway
