// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"

#include <optional>
#include <string>
#include <vector>

// The edits the IDE makes to a project's gateways and to the units'
// External communication setting, each refused with a reason when it would
// leave the project outside the manual's ranges.
namespace rs::project {

// The node addresses 0-15 no gateway of the project has.
std::vector<int> freeGatewayNodes(const Project& project);

// Adds a gateway with the manual's defaults; a node in use or out of range is refused.
std::optional<std::string> addGateway(Project& project, int node, GatewayType type);
// Replaces a gateway's settings; settings outside the manual's ranges are refused.
std::optional<std::string> setGateway(Project& project, int node, const Gateway& gateway);
// Removes a gateway; the units that receive from it keep their setting (the
// compiler warns about it), so nothing a user set is lost silently.
void removeGateway(Project& project, int node);

// Replaces a unit's External communication setting (empty: none).
std::optional<std::string> setExternalComm(Project& project, int station, const ExternalComm& comm);
ExternalComm externalCommOf(const Project& project, int station);

} // namespace rs::project
