// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <string_view>

namespace rs::lang {

enum class TokenKind : std::uint8_t {
    Word,   // letters, digits, '_' and '.': addresses, names, keywords, hex numbers
    Number, // digits only
    Time,   // digits 's' digits: 5s10
    LParen,
    RParen,
    Plus,
    Minus, // '-' and the typographic dash a copied manual line may hold
    Star,
    Slash,
    Equal,
    Less,
    Greater,
    Comma,
    Colon,
    Bang,
    Dollar,
    Comment, // text after ';' up to the end of the line
    EndOfLine,
    EndOfFile,
    Invalid, // a character the language has no use for, or bad UTF-8
};

struct Token {
    TokenKind kind = TokenKind::EndOfFile;
    std::string_view text;
    int line = 1;
    int column = 1; // in characters, not bytes
};

// Splits Pluto program text into tokens. Spaces and tabs separate tokens and
// are otherwise ignored; a line break is a token because a statement ends at
// the end of its line.
class Lexer {
public:
    explicit Lexer(std::string_view source);

    Token next();

private:
    void skipSpaces();
    void advance();
    void advanceAsciiTo(std::size_t end);
    std::size_t wordCharLength(std::size_t at) const;

    std::string_view m_source;
    std::size_t m_pos = 0;
    int m_line = 1;
    int m_column = 1;
};

bool isWordStartOrPart(char32_t c);

} // namespace rs::lang
