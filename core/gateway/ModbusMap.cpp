// SPDX-License-Identifier: GPL-3.0-or-later
#include "ModbusMap.h"

#include "GatewayData.h"

namespace rs::gateway {

namespace {

constexpr int kReadHoldingRegisters = 3;
constexpr int kWriteMultipleRegisters = 16;

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
    // Additional Data 00-31 (67-130) stay 0 until the ToGateway blocks send.
    return table;
}

ModbusResponse answer(const ModbusRequest& request, const DataFromPluto& table) {
    if (request.unit != kDataFromPlutoUnit)
        return refused(ModbusException::GatewayTargetFailed);
    if (request.function == kWriteMultipleRegisters)
        return refused(ModbusException::IllegalFunction); // unit 33 is read only
    if (request.function != kReadHoldingRegisters)
        return refused(ModbusException::IllegalFunction);
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
