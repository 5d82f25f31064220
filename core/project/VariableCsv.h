// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Project.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

// Variable names and descriptions as CSV (manual Part 1, 10.4), the way a
// spreadsheet reads and writes it: RFC 4180 quoting, ';' or ',' between
// fields (found out on reading), UTF-8 with a byte-order mark so that Excel
// takes the text as UTF-8. Columns: Variable, Symbolic Name, Description.
namespace rs::project {

enum class CsvScope { All, Global, Local };
enum class CsvOrder { ByVariable, ByName };

struct CsvExportOptions {
    std::optional<int> station; // one unit, or every unit
    CsvScope scope = CsvScope::All;
    std::string prefix; // put before every name, e.g. "Press1_"
    CsvOrder order = CsvOrder::ByVariable;
    char separator = ',';
};

// Every variable with a name or a description, one row each, with a heading row.
std::string exportVariablesCsv(const Project& project, const CsvExportOptions& options);

struct CsvImportOptions {
    std::optional<int> station; // rows of other units are refused
    std::string prefix;         // taken off the names that start with it
};

// A row that will change the project, with what it changes.
struct CsvChange {
    int line = 0;
    lang::Address address;
    std::string oldName;
    std::string name;
    std::string oldDescription;
    std::string description;
};

struct CsvProblem {
    int line = 0;   // where the offending field starts, counted from 1
    int column = 1; // in characters of that line, counted from 1
    std::string message;
};

// Bad rows listed one by one at most; more are counted in one last problem.
inline constexpr std::size_t kCsvListedProblems = 100;
// A row with more fields than this is no variable table (and would cost memory).
inline constexpr std::size_t kCsvMaxFields = 1000;

struct CsvImport {
    char separator = ',';
    std::vector<CsvChange> changes;   // rows that change something
    int unchanged = 0;                // good rows that change nothing
    std::vector<CsvProblem> problems; // bad rows, left out; in the order of the text
    Project project;                  // the project with every good row in
};

// Reads the CSV against the project. Nothing is changed: the result holds the
// project as it would be, for a preview and a confirmation. Names follow the
// language's rules; a text with a NUL byte, invalid UTF-8, an unclosed quote or
// too many fields in a row is refused as a whole (one problem, no changes).
CsvImport importVariablesCsv(const Project& project, std::string_view csv,
                             const CsvImportOptions& options);

// A field as a spreadsheet reads it back: quoted when it holds the
// separator, a quote, a line break or spaces at its ends.
std::string csvField(const std::string& field, char separator);

// The separator a CSV text uses: ';', ',' or a tab, whichever its first line
// has most of outside quotes; ',' when it has none.
char detectCsvSeparator(std::string_view csv);

struct CsvPlace {
    int line = 1;
    int column = 1; // in characters, after a leading byte-order mark
};

struct CsvRecord {
    int line = 0;
    std::vector<std::string> fields;
    std::vector<CsvPlace> places; // where each field starts
};

struct CsvSyntaxError {
    int line = 0;
    int column = 1;
    std::string message;
};

// Splits a CSV text into records (a leading byte-order mark is skipped, quoted
// fields may hold separators, quotes and line breaks, kept as written). Lines
// end at LF, CRLF or a lone CR. Throws CsvSyntaxError for a quote that is
// never closed, a row of more than kCsvMaxFields fields, a NUL byte or invalid
// UTF-8.
std::vector<CsvRecord> readCsv(std::string_view csv, char separator);

} // namespace rs::project
