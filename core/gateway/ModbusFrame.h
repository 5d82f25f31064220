// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ModbusMap.h"

#include <cstddef>
#include <cstdint>
#include <optional>

namespace rs::gateway {

// The MBAP header of a Modbus TCP frame: transaction, protocol, length, unit.
inline constexpr std::size_t kMbapHeaderLength = 7;

// The request a Modbus TCP frame carries; nothing when the bytes are no
// whole frame (shorter than a header and a function code, or a length field
// that does not match). Fields the function has not got stay 0.
std::optional<ModbusRequest> readModbusFrame(const std::uint8_t* bytes, std::size_t length);

} // namespace rs::gateway
