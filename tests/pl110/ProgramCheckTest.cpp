// SPDX-License-Identifier: GPL-3.0-or-later
#include "pl110/ProgramCheck.h"
#include "pl110/ProgramText.h"

#include <gtest/gtest.h>

namespace rs::pl110 {
namespace {

std::string problems(std::string_view body) {
    const ProgramReading reading = readProgram("$target PL110\nMAIN\n" + std::string(body));
    std::string text;
    for (const auto& d : reading.diagnostics)
        text += "read " + std::to_string(d.line) + ":" + std::to_string(d.column) + ": " +
                d.message + "\n";
    for (const auto& d : checkProgram(reading.program))
        text += std::to_string(d.line) + ":" + std::to_string(d.column) + ": " + d.message + "\n";
    return text;
}

TEST(Pl110Check, WritesGoWhereTheDatasheetAllowsThem) {
    EXPECT_EQ(problems("I1 = I2\n"), "3:1: a coil writes Q, M or B, not I1\n");
    EXPECT_EQ(problems("V3.4 = I2\n"),
              "3:1: a coil writes Q, M or B, not V3.4: SBIT and RBIT write bits of words\n");
    EXPECT_EQ(problems("SBIT(Q1) = I2\n"),
              "3:6: SBIT and RBIT write a bit of a V or SM word (V3.4), not Q1\n");
    EXPECT_EQ(problems("SBIT(SM0.1) = I2\n"), "3:6: SM0.1 is read only\n");
    EXPECT_EQ(problems("(AI1 = 5)\n"), "3:2: AI1 is read only\n");
    EXPECT_EQ(problems("(SMW6 = 5)\n"), "3:2: SMW6 is read only\n");
    EXPECT_EQ(problems("(SMD19 = 5)\n"), "3:2: SMD19 is read only\n");
    EXPECT_EQ(problems("(V1.2 = 5)\n"),
              "3:2: V1.2 is a bit: MOV and FM write a word; SBIT and RBIT write bits\n");
    EXPECT_EQ(problems("(VW1 = 40000)\n"),
              "3:8: the constant 40000 does not fit a word: -32768-32767\n");
    EXPECT_EQ(problems("(VD1 = 40000)\n(SMW16 = 20)\nSBIT(SM0.5) = I1\n(T1 = 0)\n"), "");
}

TEST(Pl110Check, ContactsReadBitsAndComparisonsReadWords) {
    EXPECT_EQ(problems("Q1 = VW3\n"),
              "3:6: VW3 is a word: a contact reads a bit (BIT contact: V1.0-V1.15)\n");
    EXPECT_EQ(problems("Q1 = (I3 > 2)\n"),
              "3:7: I3 is a bit: a word is wanted here (VW, SMW, AI, T, C, ...)\n");
    EXPECT_EQ(problems("Q1 = (T3 > 2) * T3 * (C1 <> VD4)\n"), "");
}

TEST(Pl110Check, TimersHaveOneCoilAndCountersAgree) {
    EXPECT_EQ(problems("TON(T1, 10ms, 5) = I1\nTOFF(T1, 10ms, 5) = I2\n"),
              "4:6: T1 already has its coil on line 3\n");
    EXPECT_EQ(problems("MUP(C1, UP, 5) = I1\nMDOWN(C1, DOWN, 5) = I2\nMUP(C2, UP, 5) = I1\nMUP(C2, "
                       "RESET, 6) = I2\n"),
              "4:7: C1's coils must agree on MUP or MDOWN and the preset\n"
              "6:5: C2's coils must agree on MUP or MDOWN and the preset\n");
    EXPECT_EQ(problems("TON(M1, 10ms, 5) = I1\n"),
              "3:5: a timer coil names a timer T1-T48, not M1\n");
    EXPECT_EQ(problems("TON(T2, 10ms, -1) = I1\n"), "3:15: the preset is out of range: 0-32767\n");
    EXPECT_EQ(problems("TON(T2, 10ms, EEP4) = I1\n"),
              "3:15: a preset is a constant or a word of VW, SMW or AI, not EEP4\n");
    EXPECT_EQ(problems("TON(T2, 10ms, AI1) = I1\nMUP(C3, UP, -5) = I1\n"), "");
}

} // namespace
} // namespace rs::pl110
