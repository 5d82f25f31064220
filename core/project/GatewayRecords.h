// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Annotation.h"
#include "Gateway.h"

#include <map>
#include <string>

// A gateway's record in the project's preamble (docs/file-format.md):
//   ;@gateway 0 type="GATE-E1"
namespace rs::project {

struct GatewayRecordError {
    std::string message;
};

Annotation gatewayRecord(int node, const Gateway& gateway);

// Reads a "gateway" record into the gateways by node; throws
// GatewayRecordError for a malformed one or a node given twice.
void readGatewayRecord(const Annotation& record, std::map<int, Gateway>& gateways);

} // namespace rs::project
