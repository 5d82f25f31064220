// SPDX-License-Identifier: GPL-3.0-or-later
#include "Lexer.h"

#include <QChar>

#include <array>

namespace rs::lang {

namespace {

bool isContinuationByte(unsigned char c) {
    return (c & 0xC0) == 0x80;
}

// Decodes one UTF-8 sequence at `at`; returns its length, 0 when malformed.
std::size_t decodeUtf8(std::string_view s, std::size_t at, char32_t& out) {
    auto c = static_cast<unsigned char>(s[at]);
    std::size_t length = c < 0x80           ? 1
                         : (c >> 5) == 0x6  ? 2
                         : (c >> 4) == 0xE  ? 3
                         : (c >> 3) == 0x1E ? 4
                                            : 0;
    if (length == 0 || at + length > s.size())
        return 0;
    char32_t value = length == 1   ? c
                     : length == 2 ? (c & 0x1F)
                     : length == 3 ? (c & 0x0F)
                                   : (c & 0x07);
    for (std::size_t i = 1; i < length; ++i) {
        auto cc = static_cast<unsigned char>(s[at + i]);
        if (!isContinuationByte(cc))
            return 0;
        value = (value << 6) | (cc & 0x3F);
    }
    out = value;
    return length;
}

// Looked up, not compared: every byte of every word passes here.
constexpr std::array<bool, 256> kAsciiWordChars = [] {
    std::array<bool, 256> table{};
    for (int c = 0; c < 256; ++c)
        table[static_cast<std::size_t>(c)] = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                                             (c >= '0' && c <= '9') || c == '_' || c == '.';
    return table;
}();

bool isAsciiWordChar(unsigned char c) {
    return kAsciiWordChars[c];
}

bool isAsciiDigit(char c) {
    return c >= '0' && c <= '9';
}

bool isDigits(std::string_view s) {
    if (s.empty())
        return false;
    for (char c : s)
        if (c < '0' || c > '9')
            return false;
    return true;
}

} // namespace

bool isWordStartOrPart(char32_t c) {
    return c == '_' || c == '.' || QChar::isLetterOrNumber(c);
}

Lexer::Lexer(std::string_view source) : m_source(source) {
    // A byte-order mark is not part of the program.
    if (m_source.substr(0, 3) == "\xEF\xBB\xBF")
        m_pos = 3;
}

void Lexer::advance() {
    ++m_pos;
    if (m_pos < m_source.size() && !isContinuationByte(static_cast<unsigned char>(m_source[m_pos])))
        ++m_column;
    else if (m_pos >= m_source.size())
        ++m_column;
}

// Steps over the ASCII characters up to `end` at once: each counts one column,
// except that a stray continuation byte after the last is no new character.
void Lexer::advanceAsciiTo(std::size_t end) {
    m_column += static_cast<int>(end - m_pos);
    m_pos = end;
    if (m_pos < m_source.size() && isContinuationByte(static_cast<unsigned char>(m_source[m_pos])))
        --m_column;
}

void Lexer::skipSpaces() {
    std::size_t end = m_pos;
    while (end < m_source.size() && (m_source[end] == ' ' || m_source[end] == '\t' ||
                                     m_source[end] == '\f' || m_source[end] == '\v'))
        ++end;
    if (end != m_pos)
        advanceAsciiTo(end);
}

// Length in bytes of the word character at `at`, 0 when it is none.
std::size_t Lexer::wordCharLength(std::size_t at) const {
    auto c = static_cast<unsigned char>(m_source[at]);
    if (c < 0x80)
        return isAsciiWordChar(c) ? 1 : 0;
    char32_t code = 0;
    std::size_t length = decodeUtf8(m_source, at, code);
    return length && isWordStartOrPart(code) ? length : 0;
}

Token Lexer::next() {
    skipSpaces();
    Token token;
    token.line = m_line;
    token.column = m_column;
    if (m_pos >= m_source.size()) {
        token.kind = TokenKind::EndOfFile;
        return token;
    }
    const std::size_t start = m_pos;
    auto single = [&](TokenKind kind) {
        advance();
        token.kind = kind;
        token.text = m_source.substr(start, 1);
        return token;
    };
    switch (m_source[m_pos]) {
    case '\r':
    case '\n': {
        // LF, CRLF and a lone CR each end a line.
        const std::size_t length = m_source.compare(m_pos, 2, "\r\n") == 0 ? 2 : 1;
        token.kind = TokenKind::EndOfLine;
        token.text = m_source.substr(start, length);
        m_pos += length;
        ++m_line;
        m_column = 1;
        return token;
    }
    case ';': {
        std::size_t end = m_source.find_first_of("\r\n", m_pos);
        if (end == std::string_view::npos)
            end = m_source.size();
        token.kind = TokenKind::Comment;
        token.text = m_source.substr(start + 1, end - start - 1);
        // A column counts characters: every byte but UTF-8 continuations.
        for (; m_pos < end; ++m_pos)
            if (!isContinuationByte(static_cast<unsigned char>(m_source[m_pos])))
                ++m_column;
        return token;
    }
    case '(':
        return single(TokenKind::LParen);
    case ')':
        return single(TokenKind::RParen);
    case '+':
        return single(TokenKind::Plus);
    case '-':
        return single(TokenKind::Minus);
    case '*':
        return single(TokenKind::Star);
    case '/':
        return single(TokenKind::Slash);
    case '=':
        return single(TokenKind::Equal);
    case '<':
        return single(TokenKind::Less);
    case '>':
        return single(TokenKind::Greater);
    case ',':
        return single(TokenKind::Comma);
    case ':':
        return single(TokenKind::Colon);
    case '!':
        return single(TokenKind::Bang);
    case '$':
        return single(TokenKind::Dollar);
    default:
        break;
    }
    // En dash (U+2013) and minus sign (U+2212) as printed in the manuals' tables.
    if (m_source[m_pos] == '\xE2' && (m_source.compare(m_pos, 3, "\xE2\x80\x93") == 0 ||
                                      m_source.compare(m_pos, 3, "\xE2\x88\x92") == 0)) {
        advance();
        advance();
        advance();
        token.kind = TokenKind::Minus;
        token.text = m_source.substr(start, 3);
        return token;
    }
    std::size_t length = wordCharLength(m_pos);
    if (length == 0) {
        char32_t code = 0;
        std::size_t badLength = decodeUtf8(m_source, m_pos, code);
        if (badLength == 0)
            badLength = 1;
        for (std::size_t i = 0; i < badLength; ++i)
            advance();
        token.kind = TokenKind::Invalid;
        token.text = m_source.substr(start, badLength);
        return token;
    }
    for (;;) {
        // Most words are ASCII: no character to decode.
        std::size_t end = m_pos;
        while (end < m_source.size() && isAsciiWordChar(static_cast<unsigned char>(m_source[end])))
            ++end;
        if (end != m_pos)
            advanceAsciiTo(end);
        if (m_pos >= m_source.size() || static_cast<unsigned char>(m_source[m_pos]) < 0x80 ||
            (length = wordCharLength(m_pos)) == 0)
            break;
        for (std::size_t i = 0; i < length; ++i)
            advance();
    }
    token.text = m_source.substr(start, m_pos - start);
    token.kind = TokenKind::Word;
    if (!isAsciiDigit(token.text.front())) {
        // A number or a time begins with a digit.
    } else if (isDigits(token.text)) {
        token.kind = TokenKind::Number;
    } else {
        std::size_t s = token.text.find_first_of("sS");
        if (s != std::string_view::npos && s > 0 && isDigits(token.text.substr(0, s)) &&
            isDigits(token.text.substr(s + 1)))
            token.kind = TokenKind::Time;
    }
    return token;
}

} // namespace rs::lang
