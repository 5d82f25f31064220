// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Address.h"
#include "lang/Ast.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

// The Pluto unit types as data: which variables each has, which are global,
// which terminals take which I/O options, and what instruction set 3 adds.
// The compiler's checks and the IDE's I/O and variable pages read these tables.
// Source: programming manual Part 1 section 10.2 (variables per family),
// sections 3.7, 6, 8, 9 (I/O options), 10.3 (remanent), Part 2 (system
// memories and registers) and appendix A (compatibility).
namespace rs::target {

enum class UnitType { A16, A20, B16, B20, S20, B22, D20, O2, B46, S46, D45, ASi, B42ASi };

// An inclusive run of numbers, e.g. I10..I17.
struct Range {
    int first = 0;
    int last = -1;
    bool contains(int n) const { return n >= first && n <= last; }
};

using Ranges = std::vector<Range>;

bool contains(const Ranges& ranges, int n);

enum class Access { Read, Write };

// A system memory or register the manuals name.
struct SystemVariable {
    lang::AddressKind kind; // SystemMemory or SystemRegister
    int index;
    std::string_view name;
    std::string_view function;
    Access access;
};

struct UnitTypeInfo {
    UnitType type;
    std::string_view name;    // as written in type_pluto: "B42_ASi"
    std::string_view display; // as the manuals name it: "B42 AS-i"
    lang::UnitFamily family;  // which id_pluto declaration it takes

    Ranges globalInputs{};          // I, seen by every unit on the bus
    Ranges localInputs{};           // I, this unit only
    Ranges analogInputs{};          // IA (global safety inputs that can also be analogue)
    Ranges counterInputs{};         // IA that can count pulses
    Ranges globalSafetyOutputs{};   // Q
    Ranges localSafetyOutputs{};    // Q
    Ranges nonSafetyOutputs{};      // Q
    Ranges configurableTerminals{}; // I/Q/IQ terminals whose use an I/O declaration sets
    Ranges asiGlobalSafeInputs{};   // ASi_.x
    Ranges asiLocalSafeInputs{};
    bool asiSlaves = false;  // ASi_.x.y / ASq_.x.y
    int globalMemories = 12; // GM_.0 ..
    int memoriesInstructionSet2 = 600;
    int memoriesInstructionSet3 = 600;
    int registers = 150;
    int systemMemories = 200;
    int systemRegisters = 100;
    bool remanent = false;                // R100..R131 / M100..M131 can be kept at power off
    bool testPulsesCanBeDisabled = false; // no_test_pulse on Q2, Q3
    std::vector<SystemVariable> systemVariables{}; // the named ones for this type
};

const std::vector<UnitTypeInfo>& unitTypes();
const UnitTypeInfo& unitTypeInfo(UnitType type);
// By the name in type_pluto (case-insensitive), nothing when unknown.
const UnitTypeInfo* findUnitType(std::string_view name);
// The type a unit has when the file gives no type_pluto line.
UnitType baseType(lang::UnitFamily family);

int memoryCount(const UnitTypeInfo& info, int instructionSet);

// "an A20", "a B46": the type's display name with its article, for messages.
std::string withArticle(const UnitTypeInfo& info);

// Whether the unit type has this variable at all (its own station's numbering).
bool hasVariable(const UnitTypeInfo& info, const lang::Address& address, int instructionSet);

// Whether other units on the bus see the variable (the manual's [G]).
bool isGlobal(const UnitTypeInfo& info, const lang::Address& address);

// The named system memory or register at this address, if the type names it.
const SystemVariable* systemVariable(const UnitTypeInfo& info, const lang::Address& address);

// Instructions and operands that need instruction set 3; nothing when set 2 has them.
std::optional<std::string_view> instructionSet3Feature(const lang::Address& address);

} // namespace rs::target
