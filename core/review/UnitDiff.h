// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "project/Project.h"

#include <string>
#include <vector>

namespace rs::review {

// What differs in a unit besides its networks.
struct UnitDifference {
    int station = 0;
    // "unit: added", "unit: removed", "type: changed", "ID code: changed",
    // "I/O options: changed", "exported and remanent variables: changed",
    // "names and descriptions: changed", "comments: changed"
    std::string what;

    std::string describe() const; // "Pluto 00 I/O options: changed"
    friend bool operator==(const UnitDifference&, const UnitDifference&) = default;
};

// By station, in the order of the list above. The I/O options compare as
// declared for each terminal, their order aside.
std::vector<UnitDifference> unitDifferences(const project::Project& before,
                                            const project::Project& after);

} // namespace rs::review
