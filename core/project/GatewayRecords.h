// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Annotation.h"
#include "Gateway.h"

#include <map>
#include <string>
#include <vector>

// A gateway's records in the project's preamble (docs/file-format.md):
//   ;@gateway 0 type="GATE-E1" cycle_ms="48" timeout_ms="2000" to_pluto="0,1" expected="0-3"
//   ;@gateway_area 0 5 pluto="2" io_type="101"
namespace rs::project {

struct GatewayRecordError {
    std::string message;
};

// The gateway's record, then one per additional data area in use; only
// settings other than the defaults are written.
std::vector<Annotation> gatewayRecords(int node, const Gateway& gateway);

// Reads a "gateway" or "gateway_area" record into the gateways by node;
// throws GatewayRecordError for a malformed one, a node or an area given
// twice, an area of a gateway not declared before it, or a value out of the
// manual's ranges.
void readGatewayRecord(const Annotation& record, std::map<int, Gateway>& gateways);

} // namespace rs::project
