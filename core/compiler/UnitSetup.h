// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "SystemCall.h"
#include "lang/Ast.h"
#include "lang/Diagnostic.h"
#include "target/UnitType.h"

#include <map>
#include <set>
#include <vector>

namespace rs::compiler {

// How one terminal is used, as an I/O declaration says ("! I0.5,c_pulse,non_inv").
struct TerminalDeclaration {
    lang::AddressKind kind = lang::AddressKind::Input; // Input, Output, InputOutput, AnalogInput
    std::vector<std::string> options;
    lang::SourceLocation location;
};

// What the document declares about one unit.
struct UnitSetup {
    int station = 0;
    const target::UnitTypeInfo* type = nullptr;
    int instructionSet = 2;
    lang::SourceLocation declared; // its id_pluto line, or its pgm_pluto line without one
    const lang::UnitProgram* program = nullptr;
    // Inputs and the I/Q/IQ terminals by number (I12, Q12 and IQ12 are one
    // terminal); safety outputs (Q2, Q3: no_test_pulse) and IA inputs have
    // their own numbering.
    std::map<int, TerminalDeclaration> terminals;
    std::map<int, TerminalDeclaration> safetyOutputs;
    std::map<int, TerminalDeclaration> analogTerminals;
    // Local variables the project exports to the other units on the bus
    // (manual Part 1, 10.2.1); they read them as if they were global.
    std::set<lang::Address> exported;
    // The ;@system records of its code (collectSystemCalls).
    SystemCalls systemCalls;
};

using UnitSetups = std::map<int, UnitSetup>; // by station

// Reads the units from their id_pluto, type_pluto and pgm_pluto declarations
// and their I/O declarations, reporting what contradicts itself: stations
// outside 0..31, a unit declared twice, a type of another family, code for a
// unit without an id_pluto line, I/O options the terminal cannot take.
UnitSetups collectUnits(const lang::Document& document, lang::Diagnostics& diagnostics);

// Reads the ;@system records of every unit's code into its systemCalls; a
// wrong call is an error at its record and is left out.
void collectSystemCalls(const lang::Document& document, UnitSetups& units,
                        lang::Diagnostics& diagnostics);

} // namespace rs::compiler
