// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Program.h"

#include <optional>
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

// Names an address or renames it (the rungs follow), sets its description,
// or with an empty name takes the name off (the rungs then write the
// address). A refusal says which field it concerns: 1 the name, 2 the
// description; `changed` says whether the program changed.
struct NamingProblem {
    int field = 1;
    std::string message;
};
std::optional<NamingProblem> nameAddress(Program& program, const Address& address,
                                         const std::string& name, const std::string& description,
                                         bool& changed);

// Each row as nameAddress does; bad rows are left out and reported.
NameCsvImport importNamesCsv(const Program& program, std::string_view csv);

} // namespace rs::pl110
