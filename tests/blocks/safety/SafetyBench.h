// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <gtest/gtest.h>

#include <string>

// Runs scenarios on projects that use the shipped Rungsmith_Safety library
// through body-less ;@block records, as a user's project does: the records
// are expanded from libraries/Rungsmith_Safety.rslib, the project is
// compiled and simulated.
namespace rs::safetytest {

// A project of one A20 unit: `names` are its symbolic-name declarations
// (`! I0.0=ChannelA` lines), `code` the statements of its PLC code.
std::string oneUnitProject(const std::string& names, const std::string& code, int instructionSet);

// Reads, expands and compiles `project`, then runs `scenario` on it. Holds
// when everything reads and compiles without errors, no expectation fails and
// every `expect` line of the scenario passed (a scenario that silently
// expects less cannot pass).
::testing::AssertionResult scenarioHolds(const std::string& project, const std::string& scenario);

// scenarioHolds on oneUnitProject with instruction set 2 and with 3: the
// bodies are meant to run on both.
::testing::AssertionResult holdsOnBothInstructionSets(const std::string& names,
                                                      const std::string& code,
                                                      const std::string& scenario);

} // namespace rs::safetytest
