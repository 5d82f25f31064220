// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "UnitSetup.h"

#include <optional>
#include <vector>

namespace rs::compiler {

// One unit's code checked without the others' (the text view checks as the
// user types): the addresses the other units' code uses are given instead,
// so that what is "named but never used" is what the whole check finds.
struct UnitScope {
    int station = 0;
    std::vector<lang::Address> usedByOtherUnits;
};

struct CheckOptions {
    // The original tool's preference: warn about inputs and outputs used
    // without an I/O declaration.
    bool warnUnconfiguredIo = true;
    // Only this unit's code and the names it declares are checked.
    std::optional<UnitScope> onlyUnit;
};

// Everything the manuals make an error in the code of the units, and the
// warnings a careful reviewer would give, each at the offending token.
lang::Diagnostics checkProgram(const lang::Document& document, const UnitSetups& units,
                               const CheckOptions& options);

// The addresses the code of every unit but `station` uses (what
// UnitScope::usedByOtherUnits needs), whatever its unit's names are: the
// names may change while the other units' code does not.
std::vector<lang::Address> usedByOtherUnits(const lang::Document& document, const UnitSetups& units,
                                            const CheckOptions& options, int station);

} // namespace rs::compiler
