// SPDX-License-Identifier: GPL-3.0-or-later
#include "text/PlutoLexer.h"
#include "text/ProgramEditor.h"

#include <gtest/gtest.h>

namespace {

using rs::ui::PlutoLexer;

// Style of the character at a 1-based line and column, after the editor has
// coloured the whole text as it would before painting.
class Colouring : public ::testing::Test {
protected:
    int styleAt(int line, int column) {
        editor.SendScintilla(QsciScintillaBase::SCI_COLOURISE, 0UL, -1L);
        const int position = editor.positionFromLineIndex(line - 1, column - 1);
        return static_cast<int>(editor.SendScintilla(QsciScintillaBase::SCI_GETSTYLEAT,
                                                     static_cast<unsigned long>(position)));
    }

    // The style of every character of a word that starts at a 1-based column,
    // or -1 when the characters differ.
    int wordStyle(int line, int column, int length) {
        const int first = styleAt(line, column);
        for (int i = 1; i < length; ++i)
            if (styleAt(line, column + i) != first)
                return -1;
        return first;
    }

    rs::ui::ProgramEditor editor;
};

TEST_F(Colouring, CommentAddressAndKeywordGetDifferentStyles) {
    editor.setText(QStringLiteral("Q0.2 = P(I0.1)   ; start"));
    const int address = styleAt(1, 1);
    const int keyword = styleAt(1, 8);
    const int comment = styleAt(1, 18);
    EXPECT_EQ(address, PlutoLexer::Address);
    EXPECT_EQ(keyword, PlutoLexer::Keyword);
    EXPECT_EQ(comment, PlutoLexer::Comment);
    EXPECT_NE(address, keyword);
    EXPECT_NE(keyword, comment);
    EXPECT_NE(address, comment);
    EXPECT_EQ(styleAt(1, 24), PlutoLexer::Comment) << "a comment is coloured to the line end";
}

TEST_F(Colouring, EveryAddressFormIsColouredAsOneAddress) {
    const QStringList addresses = {"I0.0",     "Q0.17",  "IQ0.14",    "IA0.1",    "M0.5",
                                   "GM0.1",    "SM0.9",  "R0.5",      "R0.5.3",   "DR0.4",
                                   "DR0.4.Lo", "SR0.43", "ASi0.1B.2", "ASq0.1.1", "q0.10"};
    editor.setText(addresses.join(QLatin1Char('\n')));
    for (int i = 0; i < addresses.size(); ++i)
        EXPECT_EQ(wordStyle(i + 1, 1, static_cast<int>(addresses[i].size())), PlutoLexer::Address)
            << addresses[i].toStdString();
}

TEST_F(Colouring, InstructionWordsAreKeywordsOnlyBeforeAParenthesis) {
    editor.setText(QStringLiteral("S(Q0.1) = TON(5s10) * /N(I0.2)\n"
                                  "T = I0.1\n"
                                  "Stop = IT(R0.5)"));
    EXPECT_EQ(styleAt(1, 1), PlutoLexer::Keyword);
    EXPECT_EQ(wordStyle(1, 11, 3), PlutoLexer::Keyword);
    EXPECT_EQ(wordStyle(1, 15, 4), PlutoLexer::Time);
    EXPECT_EQ(styleAt(1, 23), PlutoLexer::Operator);
    EXPECT_EQ(styleAt(1, 24), PlutoLexer::Keyword);
    EXPECT_EQ(styleAt(2, 1), PlutoLexer::Name) << "T without '(' is a name";
    EXPECT_EQ(wordStyle(3, 1, 4), PlutoLexer::Name);
    EXPECT_EQ(wordStyle(3, 8, 2), PlutoLexer::Keyword);
}

TEST_F(Colouring, RecordsAreSetApartFromPlainComments) {
    editor.setText(QStringLiteral(";@unit 00 description=\"Press\"\n; plain words"));
    EXPECT_EQ(wordStyle(1, 1, 29), PlutoLexer::Record);
    EXPECT_EQ(styleAt(2, 1), PlutoLexer::Comment);
}

TEST_F(Colouring, StepHeadersDeclarationsAndDirectives) {
    editor.setText(QStringLiteral("S0.1_2                 ; step\n"
                                  "R(S0.1) = I0.1\n"
                                  "! I0.5,c_pulse,non_inv\n"
                                  "! type_pluto:00=B46,is3\n"
                                  "$name Press line\n"
                                  "! id_pluto:00=000034AD4AE1"));
    EXPECT_EQ(wordStyle(1, 1, 6), PlutoLexer::StepHeader);
    EXPECT_EQ(wordStyle(2, 3, 4), PlutoLexer::Address) << "a sequence operand is no step header";
    EXPECT_EQ(styleAt(3, 1), PlutoLexer::Declaration);
    EXPECT_EQ(wordStyle(3, 3, 4), PlutoLexer::Address);
    EXPECT_EQ(wordStyle(3, 8, 7), PlutoLexer::Option);
    EXPECT_EQ(wordStyle(4, 3, 10), PlutoLexer::Declaration);
    EXPECT_EQ(wordStyle(4, 17, 3), PlutoLexer::Option);
    EXPECT_EQ(wordStyle(4, 21, 3), PlutoLexer::Option);
    EXPECT_EQ(wordStyle(5, 1, 5), PlutoLexer::Directive);
    EXPECT_EQ(wordStyle(5, 7, 5), PlutoLexer::DirectiveText);
    EXPECT_EQ(wordStyle(6, 15, 12), PlutoLexer::Number);
}

TEST_F(Colouring, WhatTheParserRejectsIsMarkedInvalid) {
    editor.setText(QStringLiteral("q0.x = I0.1 ¤ I0.2"));
    EXPECT_EQ(wordStyle(1, 1, 4), PlutoLexer::Invalid) << "malformed address";
    EXPECT_EQ(styleAt(1, 13), PlutoLexer::Invalid) << "a character the language has no use for";
    EXPECT_EQ(wordStyle(1, 15, 4), PlutoLexer::Address);
}

TEST_F(Colouring, ColumnsAfterNonAsciiNamesStayAligned) {
    // Scintilla styles bytes; the name takes more bytes than characters.
    editor.setText(QStringLiteral("Mötorström = Q0.1 ; på"));
    EXPECT_EQ(wordStyle(1, 1, 10), PlutoLexer::Name);
    EXPECT_EQ(wordStyle(1, 14, 4), PlutoLexer::Address);
    EXPECT_EQ(wordStyle(1, 19, 4), PlutoLexer::Comment);
}

TEST_F(Colouring, EditingALineRecolorsIt) {
    editor.setText(QStringLiteral("Q0.1 = I0.1"));
    ASSERT_EQ(styleAt(1, 1), PlutoLexer::Address);
    editor.setCursorPosition(0, 0);
    editor.insert(QStringLiteral("; "));
    EXPECT_EQ(styleAt(1, 3), PlutoLexer::Comment);
}

} // namespace
