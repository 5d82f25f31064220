// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "AsiOptions.h"
#include "Project.h"

#include <set>

// A unit's AS-i options in the project, and what they give the unit.
namespace rs::project {

// The unit's options; the defaults when it has none stored.
AsiOptions asiOptionsOf(const Project& project, int station);

// Stores the options; the defaults are stored as none, so a project written
// and read again is equal to itself.
void setAsiOptions(Project& project, int station, const AsiOptions& options);

// The AS-i variables the unit's defined slaves give it (the manual's table).
std::set<lang::Address> configuredAsiVariables(const Project& project, int station);

} // namespace rs::project
