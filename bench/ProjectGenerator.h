// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <string>

namespace rs::bench {

struct GeneratorOptions {
    int units = 32;               // stations 0 .. units-1, at most 32
    int statementsPerUnit = 2000; // code lines per unit, main code and sequences together
    std::uint32_t seed = 20260101;
};

// A large project of the kind a plant with many Pluto units would have, for
// benchmarks: id, type, global names, I/O declarations, local names, main
// code and sequences, with every statement form and comments. It checks with
// 0 errors, and the same options give the same bytes on every platform.
// Throws std::invalid_argument when the options are out of range.
std::string generateProject(const GeneratorOptions& options);

} // namespace rs::bench
