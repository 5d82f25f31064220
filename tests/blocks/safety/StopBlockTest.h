// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <gtest/gtest.h>

#include <ostream>
#include <string>

// SF_EmergencyStop and SF_ESPE have one state machine in the public model,
// differing only in the names of their safety input and output. The
// scenarios of StopBlockScenarios.cpp run on each through this fixture; each
// block's test file instantiates them.
namespace rs::safetytest {

struct StopBlock {
    std::string name;   // SF_EmergencyStop
    std::string input;  // S_EStopIn: on while no stop is requested
    std::string output; // S_EStopOut
};

inline void PrintTo(const StopBlock& block, std::ostream* out) {
    *out << block.name;
}

class StopBlockTest : public ::testing::TestWithParam<StopBlock> {
protected:
    // Runs the scenario on a unit holding one body-less instance of the block
    // whose safety input is SafeIn, its output Out, and Ready, Error and
    // DiagCode bound to names of their own; `bindings` adds further pins.
    ::testing::AssertionResult holds(const std::string& bindings,
                                     const std::string& scenario) const;
};

} // namespace rs::safetytest
