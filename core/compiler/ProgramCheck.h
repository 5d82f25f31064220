// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "UnitSetup.h"

namespace rs::compiler {

struct CheckOptions {
    // The original tool's preference: warn about inputs and outputs used
    // without an I/O declaration.
    bool warnUnconfiguredIo = true;
};

// Everything the manuals make an error in the code of the units, and the
// warnings a careful reviewer would give, each at the offending token.
lang::Diagnostics checkProgram(const lang::Document& document, const UnitSetups& units,
                               const CheckOptions& options);

} // namespace rs::compiler
