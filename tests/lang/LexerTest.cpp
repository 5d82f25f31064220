// SPDX-License-Identifier: GPL-3.0-or-later
#include "lang/Lexer.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

using namespace rs::lang;

namespace {

std::vector<Token> lexAll(std::string_view source) {
    Lexer lexer(source);
    std::vector<Token> tokens;
    for (Token t = lexer.next(); t.kind != TokenKind::EndOfFile; t = lexer.next())
        tokens.push_back(t);
    return tokens;
}

} // namespace

TEST(Lexer, SplitsAStatementIntoTokensWithPositions) {
    auto tokens = lexAll("q0.2 = i0.12*(p(i0.14)+q0.2) ; start\n");
    ASSERT_EQ(tokens.size(), 14u);
    EXPECT_EQ(tokens[0].kind, TokenKind::Word);
    EXPECT_EQ(tokens[0].text, "q0.2");
    EXPECT_EQ(tokens[1].kind, TokenKind::Equal);
    EXPECT_EQ(tokens[1].column, 6);
    EXPECT_EQ(tokens[3].kind, TokenKind::Star);
    EXPECT_EQ(tokens[3].column, 13);
    EXPECT_EQ(tokens[12].kind, TokenKind::Comment);
    EXPECT_EQ(tokens[12].text, " start");
    EXPECT_EQ(tokens[13].kind, TokenKind::EndOfLine);
}

TEST(Lexer, TellsTimesNumbersAndWordsApart) {
    auto tokens = lexAll("5s10 2S5 01 000034AD4AE1 R0.5");
    ASSERT_EQ(tokens.size(), 5u);
    EXPECT_EQ(tokens[0].kind, TokenKind::Time);
    EXPECT_EQ(tokens[1].kind, TokenKind::Time);
    EXPECT_EQ(tokens[2].kind, TokenKind::Number);
    EXPECT_EQ(tokens[3].kind, TokenKind::Word);
    EXPECT_EQ(tokens[4].kind, TokenKind::Word);
}

TEST(Lexer, ColumnsCountCharactersNotBytes) {
    auto tokens = lexAll("Säkerhetsgrind = Δp");
    ASSERT_EQ(tokens.size(), 3u);
    EXPECT_EQ(tokens[0].text, "Säkerhetsgrind");
    EXPECT_EQ(tokens[1].column, 16);
    EXPECT_EQ(tokens[2].text, "Δp");
    EXPECT_EQ(tokens[2].column, 18);
}

TEST(Lexer, LinesAdvanceAndTypographicDashIsMinus) {
    auto tokens = lexAll("a\n\n(R0.1 \xE2\x80\x93= 7)");
    ASSERT_GE(tokens.size(), 5u);
    EXPECT_EQ(tokens[3].line, 3);
    EXPECT_EQ(tokens[5].kind, TokenKind::Minus);
    EXPECT_EQ(tokens[6].column, 8);
}

TEST(Lexer, StrayCharactersAndBadUtf8AreInvalidTokens) {
    auto tokens = lexAll("Q0.1 # \xFF");
    ASSERT_EQ(tokens.size(), 3u);
    EXPECT_EQ(tokens[1].kind, TokenKind::Invalid);
    EXPECT_EQ(tokens[2].kind, TokenKind::Invalid);
}

TEST(Lexer, ByteOrderMarkIsSkipped) {
    auto tokens = lexAll("\xEF\xBB\xBFQ0.1");
    ASSERT_EQ(tokens.size(), 1u);
    EXPECT_EQ(tokens[0].text, "Q0.1");
    EXPECT_EQ(tokens[0].column, 1);
}

// Random bytes (words, spaces, line ends, letters of two and three bytes,
// stray continuation bytes and other bad UTF-8): every token's column counts
// the characters before it on its line, a byte that continues none being no
// new character, and its line the line ends before it.
TEST(Lexer, EveryTokensPlaceCountsTheCharactersBeforeIt) {
    const std::vector<std::string> pieces = {
        "a",    "Q0.1", "_x",   "7",    " ",    "\t", "\f",       "\n",           "\r\n",
        "\r",   ";c",   "(",    ")",    "=",    "!",  "\xC3\xA5", "\xE2\x80\x93", "\xE2\x82\xAC",
        "\x80", "\xBF", "\xC3", "\xFF", "5s10", "..", "$",
    };
    std::mt19937 random(5);
    for (int round = 0; round < 3000; ++round) {
        std::string source;
        const int count = 1 + static_cast<int>(random() % 40);
        for (int i = 0; i < count; ++i)
            source += pieces[random() % pieces.size()];
        Lexer lexer(source);
        for (Token token = lexer.next(); token.kind != TokenKind::EndOfFile; token = lexer.next()) {
            const auto at = static_cast<std::size_t>(token.text.data() - source.data());
            int line = 1;
            std::size_t lineStart = 0;
            for (std::size_t i = 0; i < at; ++i)
                if (source[i] == '\n' ||
                    (source[i] == '\r' && (i + 1 >= source.size() || source[i + 1] != '\n'))) {
                    ++line;
                    lineStart = i + 1;
                }
            // A comment's text starts after its ';'.
            const std::size_t start = token.kind == TokenKind::Comment ? at - 1 : at;
            int column = 1;
            for (std::size_t i = lineStart + 1; i <= start; ++i)
                if ((static_cast<unsigned char>(source[i]) & 0xC0) != 0x80)
                    ++column;
            ASSERT_EQ(token.line, line) << "round " << round << " at byte " << at;
            ASSERT_EQ(token.column, column) << "round " << round << " at byte " << at;
        }
    }
}
