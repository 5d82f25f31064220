// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Network.h"
#include "TextToLadder.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rs::ladder {

// The ladder of one step of a unit's code, with the number each network's
// first statement has in the unit (file order, from 0, as the compiler and
// the simulator number statements).
struct StepPage {
    lang::StepAddress address;
    StepLadder ladder;
    std::vector<std::uint32_t> firstStatements; // one per network
    std::uint32_t firstStatement = 0;           // the number of the step's first statement
};

// Every step of the unit's code in file order; block instances are boxes
// where `shown` says so (toLadder), all of them when it is not given.
using UnitBlockShown = std::function<bool(const lang::Step&, const blocks::BlockInstance&)>;
std::vector<StepPage> unitLadder(const lang::UnitProgram& unit, const UnitBlockShown& shown = {});

// A ladder page holds one scene item per network, laid out whole; beyond this
// many lines of code it would take minutes and gigabytes, so the page is not
// drawn and its text page shows the code.
inline constexpr std::size_t kMostDrawnLines = 50'000;

// The lines of the unit's code in the steps of one sequence (0: the PLC code).
std::size_t sequenceLines(const lang::UnitProgram& unit, int sequence);

// Writes a step's ladder back as the step's lines. False when the unit has no
// step at that address.
bool setStepLadder(lang::UnitProgram& unit, const lang::StepAddress& address,
                   const StepLadder& ladder);

} // namespace rs::ladder
