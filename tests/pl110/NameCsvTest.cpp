// SPDX-License-Identifier: GPL-3.0-or-later
#include "pl110/NameCsv.h"
#include "pl110/ProgramText.h"

#include <gtest/gtest.h>

namespace rs::pl110 {
namespace {

const char* const kProgram = "$target PL110\n"
                             "! I1=Start                     ; green button\n"
                             "! Q1=Pump\n"
                             "INIT\n"
                             "MAIN\n"
                             "Pump = Start * /I2\n";

Program readNamedProgram(std::string_view text) {
    ProgramReading reading = readProgram(text);
    EXPECT_TRUE(reading.diagnostics.empty());
    return reading.program;
}

TEST(Pl110NameCsv, ExportsEveryNameWithItsDescription) {
    EXPECT_EQ(
        exportNamesCsv(readNamedProgram(kProgram)),
        "\xEF\xBB\xBFVariable,Symbolic Name,Description\r\nI1,Start,green button\r\nQ1,Pump,\r\n");
}

TEST(Pl110NameCsv, ImportRenamesAddsAndRemovesAndTheRungsFollow) {
    const NameCsvImport imported =
        importNamesCsv(readNamedProgram(kProgram), "Variable;Symbolic Name;Description\n"
                                                   "I1;StartButton;\"green; lit\"\n"
                                                   "i2;Stop;red\n"
                                                   "Q1;;\n");
    ASSERT_TRUE(imported.problems.empty()) << imported.problems.front().message;
    EXPECT_EQ(imported.changed, 3);
    // A new name is declared; operands written as addresses stay as written.
    EXPECT_EQ(printProgram(imported.program), "$target PL110\n"
                                              "! I1=StartButton               ; green; lit\n"
                                              "! I2=Stop                      ; red\n"
                                              "INIT\n"
                                              "MAIN\n"
                                              "Q1 = StartButton * /I2\n");
}

TEST(Pl110NameCsv, BadRowsAreReportedAtTheirFieldAndLeftOut) {
    const NameCsvImport imported =
        importNamesCsv(readNamedProgram(kProgram), "I300,Far,\n"
                                                   "Motor,Pump2,\n"
                                                   "I3,NOT,\n"
                                                   "I4,Q7,\n"
                                                   "I5,Pump,\n"
                                                   "I6,,only a description\n"
                                                   "I7,Fine,\n");
    std::string text;
    for (const auto& p : imported.problems)
        text += std::to_string(p.line) + ":" + std::to_string(p.column) + ": " + p.message + "\n";
    EXPECT_EQ(text, "1:1: I300 is out of range: I1-I256\n"
                    "2:1: 'Motor' is not a PL110 address\n"
                    "3:4: 'NOT' is a keyword of the text form, not a name\n"
                    "4:4: 'Q7' is an address, not a name\n"
                    "5:4: 'Pump' already names another address\n"
                    "6:4: a description needs a name: the text form keeps it on the name's line\n");
    EXPECT_EQ(imported.changed, 1);
    // What export writes, import reads back to the same program.
    const Program program = readNamedProgram(kProgram);
    const NameCsvImport again = importNamesCsv(program, exportNamesCsv(program));
    EXPECT_TRUE(again.problems.empty());
    EXPECT_EQ(again.changed, 0);
    EXPECT_EQ(again.program, program);
}

} // namespace
} // namespace rs::pl110
