// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ModbusMap.h"
#include "sim/Simulation.h"

#include <array>
#include <cstdint>

// Units 2 and 34 of the Modbus map, Local Data Request and Response
// (Gateway manual Appendix D, 5.4.3): a client writes a request with the
// flag 3, the gateway asks the Pluto, and the response holds the flag 6 until
// the client writes 0 over it.
namespace rs::gateway {

inline constexpr int kLocalDataRequestUnit = 2;
inline constexpr int kLocalDataResponseUnit = 34;

struct LocalDataTables {
    // 0 flag (3 = request set), 1 Pluto 0-31 (255 the gateway), 2 data type
    // (0 global data, 1 local memory, 2 local register, 3 local parameter),
    // 3 address.
    std::array<std::uint16_t, 4> request{};
    // 0 flag (6 = new data valid), 1 Pluto, 2 data type, 3 address, 4 error
    // code, 5-6 the data, MSW first.
    std::array<std::uint16_t, 7> response{};
};

inline constexpr std::uint16_t kRequestSet = 3;
inline constexpr std::uint16_t kResponseValid = 6;

// The error codes of the response (Appendix D).
enum class LocalDataError : std::uint16_t {
    Ok = 0x0001,
    Timeout = 0x0002,
    BadData = 0x0004,
    Unknown = 0x0008,
};

// A read or write of unit 2 or 34 (both read/write).
ModbusResponse answerLocalData(const ModbusRequest& request, LocalDataTables& tables);

// Answers a request whose flag is 3 from the simulation: the response gets
// the value and the flag 6, the request's flag goes back to 0.
void serveLocalData(LocalDataTables& tables, const sim::Simulation& simulation);

} // namespace rs::gateway
