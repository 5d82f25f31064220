// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"

#include <optional>
#include <set>
#include <string>

// Export variables (manual Part 1, 10.2.1): local variables of a unit with
// instruction set 3 made visible to the other units on the bus. Each extra
// telegram pair carries 32 Boolean variables, 16 Booleans and a register, two
// registers or one double register; a unit may add 4 pairs, a project 16.
namespace rs::project {

inline constexpr int kTelegramPairsPerUnit = 4;
inline constexpr int kTelegramPairsPerProject = 16;

// Why the variable cannot be exported at all (a global variable, a kind the
// manual does not list, a unit with instruction set 2), or nothing.
std::optional<std::string> checkExportable(const Project& project, const lang::Address& address);

// Extra telegram pairs the unit's exported variables need, and the project's.
int telegramPairs(const Project& project, int station);
int telegramPairs(const Project& project);
// The same for a set of exported variables of any units.
int telegramPairs(const std::set<lang::Address>& exported, int station);

// Marks or unmarks a variable as exported; refuses (changing nothing) when it
// cannot be exported or the telegram limits would be exceeded.
std::optional<std::string> setExported(Project& project, const lang::Address& address,
                                       bool exported);

} // namespace rs::project
