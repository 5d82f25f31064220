// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Image.h"
#include "UnitSetup.h"

namespace rs::compiler {

// Translates one unit's checked code into instructions: the PLC code first,
// then each sequence by number, each step by number. A unit without code
// gives an image without steps.
UnitImage generateCode(const UnitSetup& unit);

} // namespace rs::compiler
