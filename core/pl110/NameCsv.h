// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Program.h"

#include <string>
#include <string_view>
#include <vector>

// A PL110 program's names and descriptions as CSV, in the columns Pluto
// projects use (Variable, Symbolic Name, Description; project/VariableCsv.h
// reads the CSV): a name is a declaration `! I1=Start`, its description the
// declaration's comment (docs/pl110.md, "Names and CSV").
namespace rs::pl110 {

// One row per declared name, in the order declared, with a heading row and
// a byte-order mark for spreadsheets.
std::string exportNamesCsv(const Program& program, char separator = ',');

struct NameCsvProblem {
    int line = 0;
    int column = 1;
    std::string message;
};

struct NameCsvImport {
    Program program; // with every good row in; rungs use the new names
    int changed = 0;
    std::vector<NameCsvProblem> problems; // bad rows, left out
};

// Rows name or rename an address (its rungs follow), set its description, or
// with an empty name take the name off (the rungs then write the address).
NameCsvImport importNamesCsv(const Program& program, std::string_view csv);

} // namespace rs::pl110
