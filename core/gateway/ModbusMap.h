// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "sim/Simulation.h"

#include <array>
#include <cstdint>
#include <vector>

// The Modbus TCP map of an Ethernet gateway (GATE-E1/E2, manual Appendix D)
// and the rules of ../shared/spec/gateway.md, apart from any socket: a
// request in, registers or an exception out.
namespace rs::gateway {

struct ModbusRequest {
    int unit = 0;     // the unit identifier: which of the gateway's tables
    int function = 0; // 3 read holding registers, 16 write multiple registers
    int address = 0;  // the first register, the manual's address
    int count = 0;
    std::vector<std::uint16_t> values; // function 16
};

// The two Modbus functions the gateway's tables answer.
inline constexpr int kReadHoldingRegisters = 3;
inline constexpr int kWriteMultipleRegisters = 16;

// Standard Modbus exception codes.
enum class ModbusException : std::uint8_t {
    None = 0,
    IllegalFunction = 1,
    IllegalDataAddress = 2,
    IllegalDataValue = 3,
    GatewayTargetFailed = 11, // a unit identifier the gateway has no table for
};

struct ModbusResponse {
    ModbusException exception = ModbusException::None;
    std::vector<std::uint16_t> registers; // what a read returns
};

inline constexpr int kMaxRegistersPerRequest = 100; // "Only 100 words can be read in one request"
inline constexpr int kDataFromPlutoUnit = 33;
inline constexpr int kDataFromPlutoFirst = 1;  // Node Status
inline constexpr int kDataFromPlutoLast = 130; // the LSW of Additional Data 31

// Unit 33, indexed by address (0 unused): Node Status at 1, Pluto n at
// 3 + 2n, Additional Data a at 67 + 2a, each a UDINT with its MSW first.
using DataFromPluto = std::array<std::uint16_t, kDataFromPlutoLast + 1>;
DataFromPluto dataFromPluto(const sim::Simulation& simulation);

// Unit 1, Data to Pluto, as the clients last wrote it (one table for every
// client: the last writer wins): the length 13 at 0, the areas' valid bits
// at 1, then for areas 0-3 their bits and registers 0 and 1.
inline constexpr int kDataToPlutoUnit = 1;
inline constexpr int kDataToPlutoLength = 13;
using DataToPluto = std::array<std::uint16_t, kDataToPlutoLength + 1>;
inline constexpr DataToPluto kNoDataToPluto{kDataToPlutoLength};

// The answer from unit 33 as it stood in `data`, and from or into unit 1;
// GatewayNode answers the other units.
ModbusResponse answer(const ModbusRequest& request, const DataFromPluto& data,
                      DataToPluto& toPluto);

} // namespace rs::gateway
