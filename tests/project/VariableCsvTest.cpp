// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/VariableCsv.h"
#include "ProjectText.h"
#include "project/VariableTable.h"

#include <gtest/gtest.h>

using namespace rs;
using lang::Address;
using lang::AddressKind;

namespace {

const char* kCsvProject = "$name Csv\n"
                          "! id_pluto:00=000000000000\n"
                          ";@var I0.1 description=\"Sensor; \\\"left\\\"\"\n"
                          ";@var M0.4 description=\"Two\\nlines\"\n"
                          "! type_pluto:00=A20,is3\n"
                          "! id_pluto:01=000000000000\n"
                          "! type_pluto:01=A20,is3\n"
                          "! I0.0=Zeta\n"
                          "! pgm_pluto:00\n"
                          "! M0.0=Alpha\n"
                          "S0.0_0\n"
                          "Q0.2 = Zeta * Alpha\n"
                          "! pgm_pluto:01\n"
                          "! M1.0=Other\n"
                          "S1.0_0\n";

} // namespace

TEST(VariableCsv, ExportIsExcelCompatible) {
    const project::Project p = projectFrom(kCsvProject);
    const std::string csv = project::exportVariablesCsv(p, {});
    EXPECT_EQ(csv, "\xEF\xBB\xBFVariable,Symbolic Name,Description\r\n"
                   "I0.0,Zeta,\r\n"
                   "I0.1,,\"Sensor; \"\"left\"\"\"\r\n"
                   "M0.0,Alpha,\r\n"
                   "M0.4,,\"Two\nlines\"\r\n"
                   "M1.0,Other,\r\n");
}

TEST(VariableCsv, ExportChoicesScopePrefixOrderAndSeparator) {
    const project::Project p = projectFrom(kCsvProject);
    project::CsvExportOptions options;
    options.station = 0;
    options.scope = project::CsvScope::Local;
    options.prefix = "P0_";
    options.order = project::CsvOrder::ByName;
    options.separator = ';';
    EXPECT_EQ(project::exportVariablesCsv(p, options),
              "\xEF\xBB\xBFVariable;Symbolic Name;Description\r\n"
              "M0.0;P0_Alpha;\r\n"
              "M0.4;;\"Two\nlines\"\r\n");
    options.scope = project::CsvScope::Global;
    options.prefix.clear();
    EXPECT_EQ(project::exportVariablesCsv(p, options),
              "\xEF\xBB\xBFVariable;Symbolic Name;Description\r\n"
              "I0.0;Zeta;\r\n"
              "I0.1;;\"Sensor; \"\"left\"\"\"\r\n");
}

TEST(VariableCsv, ExportThenImportChangesNothing) {
    const project::Project p = projectFrom(kCsvProject);
    for (char separator : {',', ';'}) {
        project::CsvExportOptions options;
        options.separator = separator;
        const auto imported =
            project::importVariablesCsv(p, project::exportVariablesCsv(p, options), {});
        EXPECT_EQ(imported.separator, separator);
        EXPECT_TRUE(imported.problems.empty());
        EXPECT_TRUE(imported.changes.empty());
        EXPECT_EQ(imported.unchanged, 5);
        EXPECT_TRUE(imported.project == p);
    }
}

TEST(VariableCsv, ImportSetsNamesAndDescriptionsAndReportsBadRowsByLine) {
    const project::Project p = projectFrom(kCsvProject);
    const std::string csv = "Symbolic Name;Variable;Description\n"      // 1
                            "Start;I0.2;\"Start button\nNO contact\"\n" // 2-3
                            "1bad;I0.3;\n"                              // 4
                            ";;\n"                                      // 5
                            "X;Q9.0;\n"                                 // 6
                            "X;M0.600;\n"                               // 7
                            "Alpha;M0.1;taken\n"                        // 8
                            "Twice;i0.2;\n"                             // 9
                            ";M0.0;\n"                                  // 10
                            "X;hello;\n";                               // 11
    const auto imported = project::importVariablesCsv(p, csv, {});
    EXPECT_EQ(imported.separator, ';');
    std::vector<int> lines;
    for (const auto& problem : imported.problems)
        lines.push_back(problem.line);
    EXPECT_EQ(lines, (std::vector<int>{4, 6, 7, 9, 11}));
    // M0.1 takes "Alpha" because M0.0 gives it up in the same file.
    ASSERT_EQ(imported.changes.size(), 3u);
    EXPECT_EQ(imported.changes[0].line, 2);
    EXPECT_EQ(imported.changes[0].name, "Start");
    EXPECT_EQ(imported.changes[0].description, "Start button\nNO contact");
    EXPECT_EQ(imported.changes[1].oldName, "");
    EXPECT_EQ(imported.changes[2].oldName, "Alpha");
    const project::Project& after = imported.project;
    EXPECT_EQ(project::variableName(after, {AddressKind::Input, 0, 2}), "Start");
    EXPECT_EQ(project::variableName(after, {AddressKind::Memory, 0, 1}), "Alpha");
    EXPECT_EQ(project::variableName(after, {AddressKind::Memory, 0, 0}), "");
    EXPECT_EQ(project::variableName(after, {AddressKind::Input, 0, 3}), "");
    EXPECT_NE(textOf(after).find("Q0.2 = Zeta * M0.0"), std::string::npos) << textOf(after);
    EXPECT_TRUE(isStable(after));
}

TEST(VariableCsv, ImportIntoOneUnitRefusesOtherUnitsAndTakesOffAPrefix) {
    const project::Project p = projectFrom(kCsvProject);
    project::CsvImportOptions options;
    options.station = 1;
    options.prefix = "P1_";
    const auto imported =
        project::importVariablesCsv(p, "\xEF\xBB\xBFM1.1,P1_Pump\r\nM0.1,P1_Fan\r\n", options);
    ASSERT_EQ(imported.problems.size(), 1u);
    EXPECT_EQ(imported.problems[0].line, 2);
    ASSERT_EQ(imported.changes.size(), 1u);
    EXPECT_EQ(imported.changes[0].name, "Pump");
}

TEST(VariableCsv, AnOpenQuoteIsReportedWhereItStarts) {
    const auto imported = project::importVariablesCsv(projectFrom(kCsvProject),
                                                      "Variable,Symbolic Name\nM0.1,\"Fan\n", {});
    ASSERT_EQ(imported.problems.size(), 1u);
    EXPECT_EQ(imported.problems[0].line, 2);
    EXPECT_TRUE(imported.changes.empty());
}

TEST(VariableCsv, RecordsAndSeparators) {
    EXPECT_EQ(project::detectCsvSeparator("a;b;c\n1,2"), ';');
    EXPECT_EQ(project::detectCsvSeparator("\"a;b\",c\n"), ',');
    EXPECT_EQ(project::detectCsvSeparator("a\tb\n"), '\t');
    EXPECT_EQ(project::detectCsvSeparator("single\n"), ',');
    const auto records = project::readCsv("a,\"b,\"\"c\"\"\"\r\n,\r\n\"x\ny\",z", ',');
    ASSERT_EQ(records.size(), 3u);
    EXPECT_EQ(records[0].fields, (std::vector<std::string>{"a", "b,\"c\""}));
    EXPECT_EQ(records[1].fields, (std::vector<std::string>{"", ""}));
    EXPECT_EQ(records[2].line, 3);
    EXPECT_EQ(records[2].fields, (std::vector<std::string>{"x\ny", "z"}));
}
