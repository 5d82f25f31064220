// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Image.h"
#include "UnitSetup.h"
#include "project/Project.h"

namespace rs::compiler {

// Writes into the image what the unit's declarations and the project set up
// besides its code: the I/O declarations, the exported variables and the
// remanent ones. They decide what the unit does as much as its code, so the
// image carries them and its signature covers them.
void addSetup(UnitImage& image, const UnitSetup& unit, const project::Project& project);

} // namespace rs::compiler
