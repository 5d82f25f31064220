// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"
#include "target/UnitType.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rs::project {

// The IDFIX a unit without an identifier circuit declares (Part 2, 5.1).
inline constexpr std::string_view kNoIdfix = "000000000000";

// What the unit page and the New Pluto dialog show and edit of one unit: its
// id_pluto and type_pluto declarations and its description.
struct UnitSettings {
    int station = 0;
    target::UnitType type = target::UnitType::A20;
    int instructionSet = 2;
    std::string idfix{kNoIdfix}; // 12 upper-case hexadecimal digits
    // The identifier is an IDFIX-PROG (Part 1, 5.1): a circuit the number is
    // written to (Tools > Write IDFIX, which needs the hardware).
    bool idfixProg = false;
    std::string description;
    bool declared = true; // false when the unit has code but no id_pluto line

    friend bool operator==(const UnitSettings&, const UnitSettings&) = default;
};

// Every unit of the project in station order: the units with an id_pluto
// declaration or code. A unit without a type_pluto line is the base type of
// its family with instruction set 2, as the file format says.
std::vector<UnitSettings> unitsOf(const Project& project);
std::optional<UnitSettings> unitSettings(const Project& project, int station);

// The type table of a unit, the A20's when the project has no such unit.
const target::UnitTypeInfo& unitTypeOf(const Project& project, int station);
int instructionSetOf(const Project& project, int station);

// The unit's code ("! pgm_pluto:NN" and what follows), created with an empty
// main sequence step when the unit has none yet.
lang::UnitProgram& programOf(Project& project, int station);

// Stations 0-31 that no unit of the project uses yet.
std::vector<int> freeStations(const Project& project);

// Appendix A: every type but the first A16 and B16 runs instruction set 3.
bool supportsInstructionSet3(target::UnitType type);

// Why an IDFIX is refused (not 12 hexadecimal digits), or nothing.
std::optional<std::string> checkIdfix(std::string_view idfix);

// Adds a unit: its id_pluto and type_pluto lines among the others in station
// order, its description, and code with an empty main sequence step. Returns
// why it was refused (station taken or outside 0-31, bad IDFIX, instruction
// set the type cannot run), and then changes nothing.
std::optional<std::string> addUnit(Project& project, const UnitSettings& settings);

// Changes a unit's type, instruction set, IDFIX and description; its station
// stays. I/O declarations, names, descriptions and attributes that the new
// type or instruction set cannot have are removed with it.
std::optional<std::string> changeUnit(Project& project, const UnitSettings& settings);

// How many I/O declarations, names, descriptions and attributes changeUnit
// would remove: what the user is asked about before a change of type.
int removedByChange(const Project& project, const UnitSettings& settings);

// Removes a unit with its declarations, code, global names and records.
void removeUnit(Project& project, int station);

} // namespace rs::project
