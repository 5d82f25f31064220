// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ModbusMap.h"
#include "project/Gateway.h"

#include <cstdint>
#include <vector>

// Unit 4 of the Modbus map, Gateway Configuration (Gateway manual Appendix
// D), write only: what a fieldbus PLC sets at run time in place of the
// project's settings.
namespace rs::gateway {

inline constexpr int kConfigurationUnit = 4;
inline constexpr int kConfigurationLast = 41; // the gateway node address
// The manual's length word says 36 but its table runs to address 41
// (../shared/research/gateway.md, A1): either is taken.
inline constexpr int kConfigurationLength = 36;

// Writes `values` from `address` on into `settings` of gateway `node`:
// 1 the Data to Pluto packets enabled (bits 0-3), 2 their timeout, 3-4 the
// expected nodes (MSW first), 5-36 the additional data areas (high byte the
// Pluto, low byte the IO-type, 0 unused), 37 the Data to Pluto cycle time,
// 38-40 PROFINET settings (taken, without effect), 41 the node address
// (only its own). A value out of the manual's ranges changes nothing and is
// IllegalDataValue.
ModbusException writeConfiguration(project::Gateway& settings, int node, int address,
                                   const std::vector<std::uint16_t>& values);

} // namespace rs::gateway
