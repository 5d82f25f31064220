// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"
#include "target/UnitType.h"

#include <optional>
#include <set>
#include <string>
#include <string_view>

// Remanent variables (manual Part 1, 10.3): registers R100..R131 and memories
// M100..M131 that keep their value when the power is off, on the types that
// can. When all 32 registers are remanent, no memory can be.
namespace rs::project {

inline constexpr int kFirstRemanent = 100;
inline constexpr int kLastRemanent = 131;

bool canBeRemanent(const target::UnitTypeInfo& type, const lang::Address& address);

// Why a unit's selection breaks the manual's rule, or nothing.
std::optional<std::string> checkRemanentSelection(const std::set<lang::Address>& selection);

// The remanent variables of one unit.
std::set<lang::Address> remanentOf(const Project& project, int station);

// Replaces the unit's remanent variables; refuses (and changes nothing) when
// the type has none, an address is not R100..R131/M100..M131 of that unit, or
// the rule is broken.
std::optional<std::string> setRemanent(Project& project, int station,
                                       const std::set<lang::Address>& selection);

// The record's text for one unit, runs joined: "M100-M103,R100".
std::string formatRemanentList(const std::set<lang::Address>& variables, int station);

struct RemanentListError {
    std::string message;
};

// Reads a record's text back for the station; throws RemanentListError when
// it is not a list of R/M numbers and runs in 100-131.
std::set<lang::Address> parseRemanentList(std::string_view text, int station);

} // namespace rs::project
