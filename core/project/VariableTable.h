// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"
#include "target/UnitType.h"

#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

// The Variables page as data (manual Part 1, 3.9 and 10): a unit's variables
// by kind, from the type tables, with their names, descriptions and
// attributes, and the operations that name and describe them. A name is the
// language's "! ADDRESS=Name" declaration: a global variable's stands before
// the first unit's code, a local one's in its unit's code after the I/O
// declarations (Part 2, 5.4).
namespace rs::project {

// The tabs of the page.
enum class VariableGroup {
    SafetyInputs,
    SafetyOutputs,
    NonSafetyOutputs,
    GlobalMemories,
    Memories,
    Registers,
    DoubleRegisters, // instruction set 3
    SystemMemories,
    SystemRegisters,
    AsiSlaves, // ASi_.x.y inputs and ASq_.x.y outputs of the AS-i types
};

std::vector<VariableGroup> variableGroups(const target::UnitTypeInfo& type, int instructionSet);

// The variables of a group in address order.
std::vector<lang::Address> variablesIn(const target::UnitTypeInfo& type, int station,
                                       int instructionSet, VariableGroup group);

// The group an address is listed in, if the type has it.
std::optional<VariableGroup> groupOf(const target::UnitTypeInfo& type, int instructionSet,
                                     const lang::Address& address);

struct Variable {
    lang::Address address;
    bool global = false;   // [G]
    bool exported = false; // [E]
    bool remanent = false; // [R]
    bool used = false;     // the unit's code reads or writes it
    std::string name;      // the symbolic name declared for it, empty when none
    std::string description;
    std::string_view systemName;     // "SM_Ditto", for the system variables the manuals name
    std::string_view systemFunction; // what the manuals say the system variable does
};

std::vector<Variable> variableTable(const Project& project, int station, VariableGroup group);

// The symbolic name declared for the address (globally or in its unit's code).
std::string variableName(const Project& project, const lang::Address& address);

// Addresses of the unit that have a declared name.
std::vector<lang::Address> namedAddresses(const Project& project, int station);

// Why the name cannot be given to the address (the manual's rules for the
// unit's instruction set, a word of the language, a name already given to
// another variable in the same scope), or nothing. An empty name is fine: it
// removes the name.
std::optional<std::string> checkVariableName(const Project& project, const lang::Address& address,
                                             std::string_view name);

// Names the variable, renames it in place, or (empty name) removes its
// declaration. Refuses, changing nothing, what checkVariableName refuses.
std::optional<std::string> setVariableName(Project& project, const lang::Address& address,
                                           std::string_view name);

// An empty description removes it.
void setVariableDescription(Project& project, const lang::Address& address,
                            std::string description);

// The variable an address is listed as on the Variables page: a register
// bit's register, a double register's half its double register.
lang::Address canonicalVariable(lang::Address address);

// Variables the unit's code reads or writes; register bits and double-register
// halves count for their register.
std::set<lang::Address> usedVariables(const Project& project, int station);

} // namespace rs::project
