// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <gtest/gtest.h>

#include <string>

// SF_TwoHandControlTypeII and SF_TwoHandControlTypeIII have one state machine
// in the public model but for Type III's 500 ms synchronism. The scenarios of
// TwoHandScenarios.cpp, which keep every press within 500 ms, run on each
// through this fixture; each block's test file instantiates them and adds
// what is its own.
namespace rs::safetytest {

// Runs the scenario on a unit holding one body-less instance of `block` with
// its buttons Button1 and Button2, its output Out, and Ready, Error and
// DiagCode bound to names of their own; `bindings` adds further pins.
::testing::AssertionResult twoHandHolds(const std::string& block, const std::string& bindings,
                                        const std::string& scenario);

class TwoHandTest : public ::testing::TestWithParam<std::string> {
protected:
    ::testing::AssertionResult holds(const std::string& bindings,
                                     const std::string& scenario) const {
        return twoHandHolds(GetParam(), bindings, scenario);
    }
};

} // namespace rs::safetytest
