// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Circuit.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace rs::ladder {

// Why a rung's output has power or not, read from what conducted in a scan
// (never by evaluating the logic again). A path is a way from the left rail
// to the outputs through one branch of each parallel circuit on it; elements
// are numbered as the compiler numbers them (lang/ElementNumbering.h).
struct PowerPaths {
    // Some path conducts all along.
    bool conducting = false;
    // On every path that does not conduct all along, the first element whose
    // right side has no power: what blocks that path. Each element once, in
    // pre-order (top to bottom, left to right).
    std::vector<std::uint16_t> blockers;
    // The topmost path that conducts all along, left to right; empty when
    // none does (or the rung has no condition).
    std::vector<std::uint16_t> holding;
};

// `conducts(element)`: whether the element had power at its right side.
PowerPaths powerPaths(const std::optional<Circuit>& condition,
                      const std::function<bool(std::uint16_t)>& conducts);

} // namespace rs::ladder
