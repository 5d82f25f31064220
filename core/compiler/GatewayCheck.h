// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "UnitSetup.h"
#include "project/Project.h"

namespace rs::compiler {

// What the Gateway manual states of the Pluto side (4.3.2, 4.3.4, 4.5):
// errors for a ToGateway user block whose No is not a number 1-99 or is the
// number of another user block of the same Pluto, and for an Ext block whose
// BlockNo is not 0-3; warnings where more than four ToGateway blocks can
// send in one scan, where an Ext block reads an External Comm Block the
// unit's External communication setting does not receive, and where that
// setting names a gateway the project lacks, a packet it does not send, a
// packet twice, or a timeout not above the gateway's cycle time.
void checkGatewayBlocks(const project::Project& project, const UnitSetups& units,
                        lang::Diagnostics& diagnostics);

} // namespace rs::compiler
