// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Invocation.h"

namespace rs::cli {

// serve FILE.sps [--modbus HOST:PORT] [--scenario SCN.scn] [--speed FACTOR]:
// the project simulated in real time, its Ethernet gateway's Modbus TCP map
// served to real clients (docs/gateway.md).
int runServe(const Invocation& invocation);

} // namespace rs::cli
