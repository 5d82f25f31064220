// SPDX-License-Identifier: GPL-3.0-or-later
#include "RandomProgram.h"

#include "pl110/ProgramText.h"

#include <gtest/gtest.h>

namespace rs::pl110 {
namespace {

std::string errors(const lang::Diagnostics& diagnostics) {
    std::string text;
    for (const auto& d : diagnostics)
        text += std::to_string(d.line) + ":" + std::to_string(d.column) + ": " + d.message + "\n";
    return text;
}

TEST(Pl110Text, RandomProgramsSurvivePrintingAndReading) {
    std::mt19937 random(110);
    for (int i = 0; i < 2000; ++i) {
        const Program program = testing::randomProgram(random, i % 2 == 0);
        const std::string text = printProgram(program);
        const ProgramReading reading = readProgram(text);
        ASSERT_TRUE(reading.diagnostics.empty()) << text << errors(reading.diagnostics);
        ASSERT_EQ(reading.program.declarations, program.declarations) << text;
        ASSERT_EQ(reading.program.init, program.init) << text;
        for (std::size_t line = 0; line < program.main.size(); ++line)
            ASSERT_EQ(reading.program.main.at(line), program.main[line]) << "line " << line << "\n"
                                                                         << text;
        ASSERT_EQ(reading.program, program) << text;
        ASSERT_EQ(printProgram(reading.program), text); // canonical: printing is idempotent
    }
}

TEST(Pl110Text, ReadsTheUsualSpellingsIntoTheCanonicalText) {
    const ProgramReading reading = readProgram(R"($Target pl110
$name Pump station ; with a semicolon
! i1=Start   ; the green button
! Q1=Pump

init
(vw0 = #100)
main
pump = start*/i2 + pump ;keep running
ton(t1,100MS,VW0) = pump
mup(c1, up, 5) = i3 * p
(VW2 = vw2 + -1) = (VW1<>5) * NOT
)");
    ASSERT_TRUE(reading.diagnostics.empty()) << errors(reading.diagnostics);
    EXPECT_EQ(printProgram(reading.program), R"($target PL110
$name Pump station ; with a semicolon
! I1=Start                     ; the green button
! Q1=Pump

INIT
(VW0 = 100)
MAIN
Pump = Start * /I2 + Pump      ;keep running
TON(T1, 100ms, VW0) = Pump
MUP(C1, UP, 5) = I3 * P
(VW2 = VW2 + -1) = (VW1<>5) * NOT
)");
}

TEST(Pl110Text, EachBadLineIsReportedAtItsColumnAndTheRestIsRead) {
    const ProgramReading reading = readProgram(R"($target PL110
! I1=Start
! I2=Start
MAIN
Q1 = I0
Q2 = /(I1 + I2)
TON(T1, 5ms, 10) = I1
MUP(C1, SIDEWAYS, 1) = I1
Q3 = Nothing
Q4 = Start
(VW1 = 99999999999)
Q5 = I1 *
)");
    EXPECT_EQ(errors(reading.diagnostics),
              "3:6: 'Start' is declared twice\n"
              "5:6: I0 is out of range: I1-I256\n"
              "6:7: negation applies to one contact: /I1\n"
              "7:9: the time base is 10ms, 100ms or 1s, not '5ms'\n"
              "8:9: a counter's input is UP, DOWN or RESET, not 'SIDEWAYS'\n"
              "9:6: 'Nothing' is neither an address nor a declared name\n"
              "11:8: the constant is out of range: -2147483648-2147483647\n"
              "12:10: expected a contact, found end of line\n");
    ASSERT_EQ(reading.program.main.size(), 1U); // Q4 = Start
}

TEST(Pl110Text, KnowsItsOwnFiles) {
    EXPECT_TRUE(isPl110Text("\n; a program\n$target PL110\nMAIN\n"));
    EXPECT_TRUE(isPl110Text("$TARGET   pl110 ; comment"));
    EXPECT_FALSE(isPl110Text("$name Emergency stop\n! id_pluto:00=000034AD4AE1\n"));
    EXPECT_FALSE(isPl110Text(""));
    const ProgramReading pluto = readProgram("$name x\nMAIN\n");
    EXPECT_EQ(errors(pluto.diagnostics), "1:1: a PL110 program starts with \"$target PL110\"\n");
}

TEST(Pl110Text, RefusesNamesThatAreKeywordsOrAddresses) {
    const ProgramReading reading = readProgram("$target PL110\n! I1=NOT\n! I2=VW3\n! I3=p\nMAIN\n");
    EXPECT_EQ(errors(reading.diagnostics), "2:6: 'NOT' is a keyword of the text form, not a name\n"
                                           "3:6: 'VW3' is an address, not a name\n"
                                           "4:6: 'p' is a keyword of the text form, not a name\n");
}

TEST(Pl110Text, NestingIsBounded) {
    std::string deep = "$target PL110\nMAIN\nQ1 = ";
    for (int i = 0; i < 200; ++i)
        deep += "(I1 + ";
    deep += "I2";
    for (int i = 0; i < 200; ++i)
        deep += ")";
    const ProgramReading reading = readProgram(deep + "\n");
    ASSERT_EQ(reading.diagnostics.size(), 1U);
    EXPECT_EQ(reading.diagnostics[0].message, "the condition nests more than 64 groups deep");
}

} // namespace
} // namespace rs::pl110
