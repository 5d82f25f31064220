// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"
#include "lang/Diagnostic.h"

#include <string>
#include <string_view>

// The text view of one unit: its code as a text of its own, from its
// "! pgm_pluto:NN" line up to the next unit's, and that text read back into
// the project. Global names, the units' id_pluto and type_pluto lines and the
// records stay where the other pages edit them.
namespace rs::project {

// The unit's code in canonical form; "! pgm_pluto:NN" alone for a unit with no code yet.
std::string unitText(const Project& project, int station);

struct UnitTextResult {
    Project project;               // the project with the unit's code replaced
    lang::Diagnostics diagnostics; // lines and columns of the unit's text

    bool ok() const { return lang::errorCount(diagnostics) == 0; }
};

// Reads the unit's text with the rest of the project around it: its names
// resolve against the global ones, ";@" records in it become the project's.
// The text must be the code of this unit alone.
UnitTextResult readUnitText(const Project& project, int station, std::string_view text);
// The same, into the project without the other units' code (withOnlyCodeOf),
// for ProjectDocument::replaceUnitCode: the cost is that of the unit.
UnitTextResult readUnitCode(const Project& project, int station, std::string_view text);

// The project with the code of every other unit left out (their
// declarations stay): all a check of this unit's code reads, a small part of
// a large project to copy.
Project withOnlyCodeOf(const Project& project, int station);

} // namespace rs::project
