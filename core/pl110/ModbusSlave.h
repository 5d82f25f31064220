// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ScanEngine.h"

#include <cstdint>
#include <span>
#include <vector>

// The PL110's Modbus slave map (datasheet section 3; docs/pl110.md, "Modbus")
// over the memory of a running program: one request's PDU in, the answer's
// PDU out. The transport (RTU framing, the CRC, the slave address) is the
// caller's.
namespace rs::pl110 {

inline constexpr int kMaxWordsPerRequest = 30; // "max 30 word" (datasheet L1017)
inline constexpr int kMaxBitsPerRequest = 2000;

// Answers a request: function code and data. A function the PL110 does not
// serve, an address it does not map or may not write, a count out of range:
// the Modbus exception (function | 0x80, then the code).
std::vector<std::uint8_t> answerRequest(Memory& memory, std::span<const std::uint8_t> request);

} // namespace rs::pl110
