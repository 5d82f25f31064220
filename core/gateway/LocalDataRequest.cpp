// SPDX-License-Identifier: GPL-3.0-or-later
#include "LocalDataRequest.h"

#include "GatewayData.h"
#include "target/UnitType.h"

#include <algorithm>
#include <optional>

namespace rs::gateway {

namespace {

using target::UnitType;

enum DataType : std::uint16_t { GlobalData = 0, LocalMemory = 1, LocalRegister = 2, Parameter = 3 };

template <std::size_t N>
ModbusResponse readOrWrite(const ModbusRequest& request, std::array<std::uint16_t, N>& table) {
    const bool read = request.function == kReadHoldingRegisters;
    const bool write = request.function == kWriteMultipleRegisters;
    if (!read && !write)
        return {ModbusException::IllegalFunction, {}};
    if (request.count < 1 || request.count > kMaxRegistersPerRequest ||
        (write && request.values.size() != static_cast<std::size_t>(request.count)))
        return {ModbusException::IllegalDataValue, {}};
    if (request.address < 0 || request.address + request.count > static_cast<int>(N))
        return {ModbusException::IllegalDataAddress, {}};
    const auto first = table.begin() + request.address;
    if (read)
        return {ModbusException::None, {first, first + request.count}};
    std::copy(request.values.begin(), request.values.end(), first);
    return {};
}

// A run of local bit addresses and the variables they stand for.
struct BitRun {
    int first; // local data address
    int last;
    lang::AddressKind kind;
    int number; // of the variable at `first`
};

// The local bit addresses of each family (Gateway manual 5.4.3.4). The
// Pluto numbers are written in Pluto's decimal-looking octal (I20..I27,
// I30..): each run is one decade.
std::vector<BitRun> bitRuns(UnitType type) {
    using K = lang::AddressKind;
    switch (type) {
    case UnitType::B46:
    case UnitType::S46:
    case UnitType::D45:
        return {{0, 7, K::Output, 10},         {8, 15, K::Output, 20},
                {16, 215, K::SystemMemory, 0}, {216, 991, K::Memory, 0},
                {992, 999, K::Input, 20},      {1000, 1007, K::Input, 30},
                {1008, 1015, K::Input, 40},    {1020, 1021, K::Output, 4}};
    case UnitType::ASi:
        return {{0, 3, K::Output, 10},    {9, 11, K::Input, 1},
                {12, 15, K::Input, 10},   {16, 215, K::SystemMemory, 0},
                {216, 511, K::Memory, 0}, {512, 527, K::AsiInput, 16}};
    case UnitType::B42ASi:
        return {{0, 7, K::Output, 10},     {8, 15, K::Output, 20},   {16, 215, K::SystemMemory, 0},
                {216, 455, K::Memory, 0},  {456, 463, K::Input, 10}, {464, 471, K::Input, 20},
                {472, 479, K::Input, 30},  {480, 487, K::Input, 40}, {488, 493, K::Output, 0},
                {497, 527, K::AsiInput, 1}};
    case UnitType::O2:
        return {{0, 1, K::Output, 10}, {16, 215, K::SystemMemory, 0}, {216, 1023, K::Memory, 0}};
    case UnitType::B22:
        return {{0, 7, K::Output, 10},
                {8, 13, K::Input, 20},
                {16, 215, K::SystemMemory, 0},
                {216, 1023, K::Memory, 0}};
    default: // the A20 family
        return {{0, 7, K::Output, 10}, {16, 215, K::SystemMemory, 0}, {216, 1023, K::Memory, 0}};
    }
}

std::optional<lang::Address> localBit(UnitType type, int station, int address) {
    for (const BitRun& run : bitRuns(type))
        if (address >= run.first && address <= run.last)
            return lang::Address{run.kind, station, run.number + address - run.first};
    return std::nullopt;
}

// SR0-99 at 0-99, R0-R347 at 100-447.
std::optional<lang::Address> localRegister(int station, int address) {
    if (address >= 0 && address < 100)
        return lang::Address{lang::AddressKind::SystemRegister, station, address};
    if (address >= 100 && address < 448)
        return lang::Address{lang::AddressKind::Register, station, address - 100};
    return std::nullopt;
}

} // namespace

ModbusResponse answerLocalData(const ModbusRequest& request, LocalDataTables& tables) {
    if (request.unit == kLocalDataRequestUnit)
        return readOrWrite(request, tables.request);
    return readOrWrite(request, tables.response);
}

void serveLocalData(LocalDataTables& tables, const sim::Simulation& simulation) {
    auto& request = tables.request;
    if (request[0] != kRequestSet)
        return;
    const int station = request[1];
    const std::uint16_t type = request[2];
    const int address = request[3];
    LocalDataError error = LocalDataError::Ok;
    std::uint32_t value = 0;
    const sim::UnitEngine* unit = station < 32 ? simulation.unit(station) : nullptr;
    if (station == 255 || type == Parameter || type > Parameter) {
        // The gateway's own registers and the Plutos' parameters are not simulated.
        error = LocalDataError::Unknown;
    } else if (!unit || !simulation.isOnBus(station)) {
        error = LocalDataError::Timeout; // no Pluto answers
    } else if (type == GlobalData) {
        if (address < 32)
            value = (globalData(simulation, station) >> address) & 1u;
        else
            error = LocalDataError::BadData;
    } else {
        const auto unitType = static_cast<UnitType>(unit->image().unitType);
        const auto variable = type == LocalMemory ? localBit(unitType, station, address)
                                                  : localRegister(station, address);
        if (variable)
            value = static_cast<std::uint32_t>(simulation.value(*variable));
        else
            error = LocalDataError::BadData;
    }
    // A register is a uint16; a system register keeps its 32 bits.
    if (type == LocalRegister && address >= 100)
        value &= 0xFFFFu;
    tables.response = {kResponseValid,
                       static_cast<std::uint16_t>(station),
                       type,
                       static_cast<std::uint16_t>(address),
                       static_cast<std::uint16_t>(error),
                       static_cast<std::uint16_t>(value >> 16),
                       static_cast<std::uint16_t>(value & 0xFFFFu)};
    request[0] = 0;
}

} // namespace rs::gateway
