// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectText.h"
#include "project/ProjectFile.h"
#include "project/VariableCsv.h"

#include <gtest/gtest.h>

using namespace rs;
using namespace std::string_literals;

namespace {

const char* kCsvReadingProject = "$name Csv\n"
                                 "! id_pluto:00=000000000000\n"
                                 "! type_pluto:00=A20,is3\n"
                                 "! I0.0=Start\n"
                                 "! pgm_pluto:00\n"
                                 "S0.0_0\n"
                                 "Q0.2 = Start\n";

const std::string kHeading = "Variable,Symbolic Name,Description\r\n";

struct Problem {
    int line;
    int column;
    std::string message;
    friend bool operator==(const Problem&, const Problem&) = default;
    friend std::ostream& operator<<(std::ostream& out, const Problem& p) {
        return out << p.line << ":" << p.column << ": " << p.message;
    }
};

std::vector<Problem> problemsOf(const project::CsvImport& imported) {
    std::vector<Problem> problems;
    for (const auto& problem : imported.problems)
        problems.push_back({problem.line, problem.column, problem.message});
    return problems;
}

project::CsvImport import(std::string_view csv) {
    return project::importVariablesCsv(projectFrom(kCsvReadingProject), csv, {});
}

} // namespace

TEST(VariableCsvReading, NamesFollowTheLexersRulesAByteOrderMarkIncluded) {
    const project::CsvImport imported =
        import(kHeading + "I0.0,\xEF\xBB\xBFStart,\r\nI0.1,Stop\xEF\xBB\xBF,\r\n");
    ASSERT_EQ(imported.problems.size(), 2u);
    EXPECT_EQ(imported.problems[0].line, 2);
    EXPECT_EQ(imported.problems[0].column, 6);
    EXPECT_EQ(imported.problems[1].line, 3);
    EXPECT_EQ(imported.problems[1].column, 6);
    // What is imported reads back without errors.
    EXPECT_TRUE(project::readProject(project::writeProject(imported.project)).ok());
}

TEST(VariableCsvReading, LineBreaksInDescriptionsSurviveExportImportExport) {
    const std::vector<std::string> descriptions{"crlf\r\nend", "cr\rend", "lf\nend", "\r\n\r\r\n\n",
                                                "tab\there"};
    std::string csv = kHeading;
    for (std::size_t i = 0; i < descriptions.size(); ++i)
        csv += "M0." + std::to_string(i) + ",,\"" + descriptions[i] + "\"\r\n";
    const project::CsvImport first = import(csv);
    ASSERT_TRUE(first.problems.empty()) << first.problems.front().message;
    // Through the project's text, as a saved project is.
    const project::Project saved = projectFrom(project::writeProject(first.project));
    for (std::size_t i = 0; i < descriptions.size(); ++i)
        EXPECT_EQ(
            saved.variableDescriptions.at({lang::AddressKind::Memory, 0, static_cast<int>(i)}),
            descriptions[i]);
    const std::string exported = project::exportVariablesCsv(saved, {});
    const project::CsvImport second = project::importVariablesCsv(saved, exported, {});
    ASSERT_TRUE(second.problems.empty()) << second.problems.front().message;
    EXPECT_EQ(second.unchanged, static_cast<int>(descriptions.size()) + 1);
    EXPECT_EQ(project::exportVariablesCsv(projectFrom(project::writeProject(second.project)), {}),
              exported);
}

TEST(VariableCsvReading, NulBytesAndInvalidUtf8AreRefusedWhereTheyAre) {
    const std::string nul = kHeading + "I0.0,Start,\r\nI0.1,Stop,two\0bytes\r\n"s;
    project::CsvImport imported = import(nul);
    EXPECT_EQ(problemsOf(imported), (std::vector<Problem>{{3, 14, "NUL byte: not text"}}));
    EXPECT_TRUE(imported.changes.empty());
    EXPECT_TRUE(imported.project.variableDescriptions.empty());

    // "é" counts as one character; a Latin-1 "é" is no UTF-8.
    imported = import("\xEF\xBB\xBF" + kHeading + "I0.1,Stop,\xC3\xA9t\xE9\r\n");
    EXPECT_EQ(problemsOf(imported),
              (std::vector<Problem>{{2, 13, "invalid UTF-8: the file must be UTF-8 text"}}));
    EXPECT_TRUE(imported.changes.empty());
    // Overlong forms and surrogates are not UTF-8 either.
    EXPECT_FALSE(import(kHeading + "I0.1,Stop,\xC0\xAF\r\n").problems.empty());
    EXPECT_FALSE(import(kHeading + "I0.1,Stop,\xED\xA0\x80\r\n").problems.empty());
}

TEST(VariableCsvReading, EveryProblemHasTheColumnOfItsField) {
    const project::CsvImport imported =
        import(kHeading + "I0.1,Stop,\r\nX9,Foo,\r\n\"I0.2\n\",Other,\r\nI0.3,  1bad,x\r\n"
                          "I0.4,Ok,\"never\r\n");
    EXPECT_EQ(problemsOf(imported),
              (std::vector<Problem>{{7, 9, "a quoted field is never closed"}}));
    const project::CsvImport rows = import(kHeading + "I0.1,Stop,\r\nX9,Foo,\r\n"
                                                      "I0.3;x,\xC3\xA9\xC3\xA9,1bad,x\r\nI0.4\r\n");
    EXPECT_EQ(problemsOf(rows),
              (std::vector<Problem>{{3, 1, "'X9' is not a variable such as I0.0 or M1.12"},
                                    {4, 1, "'I0.3;x' is not a variable such as I0.0 or M1.12"}}));
    // A field after one with a line break starts on the line the break begins.
    const project::CsvImport later = import("Description,Variable,Symbolic Name\r\n"
                                            "\"one\r\ntwo\",X9,Foo\r\n");
    EXPECT_EQ(problemsOf(later),
              (std::vector<Problem>{{3, 6, "'X9' is not a variable such as I0.0 or M1.12"}}));
    const project::CsvImport names = import(kHeading + "I0.1,Stop,\r\nI0.2,\xC3\xA9,1bad\r\n"
                                                       "I0.3,x y\r\n");
    ASSERT_EQ(names.problems.size(), 1u);
    EXPECT_EQ(names.problems[0].line, 4);
    EXPECT_EQ(names.problems[0].column, 6);
}

TEST(VariableCsvReading, ALoneCarriageReturnEndsARow) {
    const project::CsvImport imported = import("Variable,Symbolic Name\rI0.1,Stop\rX,Y\rI0.2,Go\r");
    EXPECT_EQ(problemsOf(imported),
              (std::vector<Problem>{{3, 1, "'X' is not a variable such as I0.0 or M1.12"}}));
    ASSERT_EQ(imported.changes.size(), 2u);
    EXPECT_EQ(imported.changes[1].line, 4);
}

TEST(VariableCsvReading, MemoryStaysBoundedByRowsAndProblems) {
    // A row of more fields than any variable table has is refused as a whole.
    const project::CsvImport wide = import(kHeading + "I0.1" + std::string(1000, ',') + "\r\n");
    EXPECT_EQ(problemsOf(wide),
              (std::vector<Problem>{{2, 1005, "a row has more than 1000 fields"}}));
    // Bad rows are listed up to a number, then counted.
    std::string csv = kHeading;
    for (int i = 0; i < 150; ++i)
        csv += "X,Y\r\n";
    const project::CsvImport bad = import(csv);
    ASSERT_EQ(bad.problems.size(), project::kCsvListedProblems + 1);
    EXPECT_EQ(bad.problems.back().line, 102);
    EXPECT_EQ(bad.problems.back().message, "50 more bad rows, not listed");
}

// Found by the fuzzer: a sequence took a name, and the project failed to read back.
TEST(VariableCsvReading, ASequenceTakesNoName) {
    const project::CsvImport imported = import("S0.7;er\n");
    EXPECT_EQ(problemsOf(imported),
              (std::vector<Problem>{{1, 1, "'S0.7' is not a variable such as I0.0 or M1.12"}}));
    EXPECT_TRUE(project::readProject(project::writeProject(imported.project)).ok());
}
