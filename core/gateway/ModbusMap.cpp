// SPDX-License-Identifier: GPL-3.0-or-later
#include "ModbusMap.h"

#include "GatewayData.h"

#include <algorithm>

namespace rs::gateway {

namespace {

void put(DataFromPluto& table, int address, std::uint32_t value) {
    table[static_cast<std::size_t>(address)] = static_cast<std::uint16_t>(value >> 16);
    table[static_cast<std::size_t>(address) + 1] = static_cast<std::uint16_t>(value & 0xFFFF);
}

ModbusResponse refused(ModbusException exception) {
    return {exception, {}};
}

} // namespace

DataFromPluto dataFromPluto(const sim::Simulation& simulation) {
    DataFromPluto table{};
    put(table, 1, nodeStatus(simulation));
    for (int station = 0; station < 32; ++station)
        put(table, 3 + 2 * station, globalData(simulation, station));
    // Additional Data 00-31 (67-130) are the gateway's (GatewayNode).
    return table;
}

ModbusResponse answer(const ModbusRequest& request, const DataFromPluto& table,
                      DataToPluto& toPluto) {
    const bool read = request.function == kReadHoldingRegisters;
    const bool write = request.function == kWriteMultipleRegisters;
    if (request.unit == kDataToPlutoUnit) {
        if (!read && !write)
            return refused(ModbusException::IllegalFunction);
        if (request.count < 1 || request.count > kMaxRegistersPerRequest ||
            (write && request.values.size() != static_cast<std::size_t>(request.count)))
            return refused(ModbusException::IllegalDataValue);
        if (request.address < 0 || request.address + request.count - 1 > kDataToPlutoLength)
            return refused(ModbusException::IllegalDataAddress);
        const auto first = toPluto.begin() + request.address;
        if (read)
            return {ModbusException::None, {first, first + request.count}};
        // The length word says what the table is; it cannot be changed.
        if (request.address == 0 && request.values.front() != kDataToPlutoLength)
            return refused(ModbusException::IllegalDataValue);
        std::copy(request.values.begin(), request.values.end(), first);
        return {};
    }
    if (request.unit != kDataFromPlutoUnit)
        return refused(ModbusException::GatewayTargetFailed);
    if (!read)
        return refused(ModbusException::IllegalFunction); // unit 33 is read only
    if (request.count < 1 || request.count > kMaxRegistersPerRequest)
        return refused(ModbusException::IllegalDataValue);
    if (request.address < kDataFromPlutoFirst ||
        request.address + request.count - 1 > kDataFromPlutoLast)
        return refused(ModbusException::IllegalDataAddress);
    ModbusResponse response;
    response.registers.assign(table.begin() + request.address,
                              table.begin() + request.address + request.count);
    return response;
}

} // namespace rs::gateway
