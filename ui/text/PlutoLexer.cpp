// SPDX-License-Identifier: GPL-3.0-or-later
#include "text/PlutoLexer.h"

#include "lang/Address.h"
#include "lang/Keywords.h"
#include "lang/Lexer.h"
#include "lang/Parser.h"

#include <Qsci/qsciscintilla.h>

#include <QFontDatabase>

#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>
#include <vector>

namespace rs::ui {

namespace {

using lang::Token;
using lang::TokenKind;

struct Span {
    std::size_t begin = 0;
    std::size_t length = 0;
    PlutoLexer::Style style = PlutoLexer::Default;
};

enum class LineKind { Statement, Declaration, Directive };

std::string lowerCase(std::string_view text) {
    std::string lower(text);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return lower;
}

bool isOneOf(const std::vector<std::string_view>& words, std::string_view lower) {
    return std::any_of(words.begin(), words.end(),
                       [lower](std::string_view word) { return lowerCase(word) == lower; });
}

bool isHexDigits(std::string_view text) {
    return !text.empty() && std::all_of(text.begin(), text.end(),
                                        [](unsigned char c) { return std::isxdigit(c) != 0; });
}

std::vector<Token> tokensOf(std::string_view line) {
    lang::Lexer lexer(line);
    std::vector<Token> tokens;
    for (Token token = lexer.next();
         token.kind != TokenKind::EndOfFile && token.kind != TokenKind::EndOfLine;
         token = lexer.next())
        tokens.push_back(token);
    return tokens;
}

PlutoLexer::Style wordStyle(const std::vector<Token>& tokens, std::size_t i, LineKind kind) {
    const Token& token = tokens[i];
    const lang::AddressWord word = lang::readAddressWord(token.text);
    switch (word.shape) {
    case lang::AddressWord::Shape::Step:
        return PlutoLexer::StepHeader;
    case lang::AddressWord::Shape::Variable:
        return PlutoLexer::Address;
    case lang::AddressWord::Shape::Malformed:
        return PlutoLexer::Invalid;
    case lang::AddressWord::Shape::NotAnAddress:
        break;
    }
    const std::string lower = lowerCase(token.text);
    if (kind == LineKind::Declaration) {
        if (i == 1)
            return isOneOf(lang::declarationWords(), lower) ? PlutoLexer::Declaration
                                                            : PlutoLexer::Name;
        if (lang::isKnownIoOption(lower) || !lang::canonicalUnitType(lower).empty() ||
            lang::instructionSetOf(lower) != 0)
            return PlutoLexer::Option;
        // The IDFIX number of "! id_pluto:00=000034AD4AE1".
        if (lowerCase(tokens[1].text)
                .starts_with(lowerCase(lang::idKeyword(lang::UnitFamily::Pluto))) &&
            tokens[i - 1].kind == TokenKind::Equal && isHexDigits(token.text))
            return PlutoLexer::Number;
        return PlutoLexer::Name;
    }
    if (i + 1 < tokens.size() && tokens[i + 1].kind == TokenKind::LParen &&
        isOneOf(lang::instructionWords(), lower))
        return PlutoLexer::Keyword;
    return PlutoLexer::Name;
}

PlutoLexer::Style tokenStyle(const std::vector<Token>& tokens, std::size_t i, LineKind kind) {
    const Token& token = tokens[i];
    if (kind == LineKind::Directive && i > 0)
        return i == 1 && token.kind == TokenKind::Word ? PlutoLexer::Directive
                                                       : PlutoLexer::DirectiveText;
    switch (token.kind) {
    case TokenKind::Word:
        return wordStyle(tokens, i, kind);
    case TokenKind::Number:
        return PlutoLexer::Number;
    case TokenKind::Time:
        return PlutoLexer::Time;
    case TokenKind::Bang:
        return i == 0 ? PlutoLexer::Declaration : PlutoLexer::Invalid;
    case TokenKind::Dollar:
        return i == 0 ? PlutoLexer::Directive : PlutoLexer::Invalid;
    case TokenKind::Invalid:
        return PlutoLexer::Invalid;
    default:
        return PlutoLexer::Operator;
    }
}

// Spans in ascending order; bytes between them keep the default style.
std::vector<Span> spansOf(std::string_view line) {
    const std::vector<Token> tokens = tokensOf(line);
    LineKind kind = LineKind::Statement;
    if (!tokens.empty() && tokens[0].kind == TokenKind::Bang)
        kind = LineKind::Declaration;
    else if (!tokens.empty() && tokens[0].kind == TokenKind::Dollar)
        kind = LineKind::Directive;

    std::vector<Span> spans;
    spans.reserve(tokens.size());
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const Token& token = tokens[i];
        const auto begin = static_cast<std::size_t>(token.text.data() - line.data());
        if (token.kind == TokenKind::Comment) {
            // The token's text starts after the ';', the colour starts at it.
            const bool record = token.text.starts_with('@');
            spans.push_back({begin - 1, line.size() - begin + 1,
                             record ? PlutoLexer::Record : PlutoLexer::Comment});
            break;
        }
        spans.push_back({begin, token.text.size(), tokenStyle(tokens, i, kind)});
    }
    return spans;
}

QColor rgb(unsigned value) {
    return QColor::fromRgb(value);
}

} // namespace

PlutoLexer::PlutoLexer(QObject* parent) : QsciLexerCustom(parent) {}

const char* PlutoLexer::language() const {
    return "Pluto";
}

QString PlutoLexer::description(int style) const {
    switch (style) {
    case Default:
        return tr("Default");
    case Comment:
        return tr("Comment");
    case Record:
        return tr("Structured record");
    case Declaration:
        return tr("Declaration");
    case Option:
        return tr("Declaration option");
    case Directive:
        return tr("Directive");
    case DirectiveText:
        return tr("Directive text");
    case StepHeader:
        return tr("Step header");
    case Address:
        return tr("Address");
    case Keyword:
        return tr("Instruction");
    case Time:
        return tr("Time constant");
    case Number:
        return tr("Number");
    case Operator:
        return tr("Operator");
    case Name:
        return tr("Symbolic name");
    case Invalid:
        return tr("Invalid text");
    default:
        return {};
    }
}

QColor PlutoLexer::defaultColor(int style) const {
    // Light, dark.
    auto pick = [this](unsigned light, unsigned dark) {
        return rgb(m_dark ? dark : light);
    };
    switch (style) {
    case Comment:
        return pick(0x6e7781, 0x8b949e);
    case Record:
        return pick(0x1a7f37, 0x7ee787);
    case Declaration:
    case Option:
    case Directive:
        return pick(0x8250df, 0xd2a8ff);
    case DirectiveText:
        return pick(0x0a3069, 0xa5d6ff);
    case StepHeader:
        return pick(0x953800, 0xffa657);
    case Address:
        return pick(0x0550ae, 0x79c0ff);
    case Keyword:
        return pick(0xa626a4, 0xf778ba);
    case Time:
    case Number:
        return pick(0x0a6e74, 0x56d4dd);
    case Operator:
        return pick(0x57606a, 0x8b949e);
    case Invalid:
        return pick(0xa40e26, 0xffa198);
    default:
        return pick(0x1f2328, 0xe6edf3);
    }
}

QColor PlutoLexer::defaultPaper(int style) const {
    if (style == Invalid)
        return rgb(m_dark ? 0x490202 : 0xffebe9);
    return rgb(m_dark ? 0x1e1f22 : 0xffffff);
}

void PlutoLexer::setDark(bool dark) {
    m_dark = dark;
    for (int style = Default; style < StyleCount; ++style) {
        setColor(defaultColor(style), style);
        setPaper(defaultPaper(style), style);
    }
    setDefaultPaper(defaultPaper(Default));
    setDefaultColor(defaultColor(Default));
}

QFont PlutoLexer::defaultFont(int style) const {
    QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    font.setPointSize(std::max(font.pointSize(), 10));
    switch (style) {
    case Declaration:
    case Directive:
    case StepHeader:
    case Keyword:
        font.setBold(true);
        break;
    case Comment:
        font.setItalic(true);
        break;
    default:
        break;
    }
    return font;
}

const char* PlutoLexer::wordCharacters() const {
    return "0123456789_.abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ";
}

void PlutoLexer::styleText(int start, int end) {
    QsciScintilla* text = editor();
    if (!text)
        return;
    // Style whole lines, so each line is read as the parser reads it.
    const auto firstLine = static_cast<int>(text->SendScintilla(
        QsciScintillaBase::SCI_LINEFROMPOSITION, static_cast<unsigned long>(start)));
    const auto lastLine = static_cast<int>(text->SendScintilla(
        QsciScintillaBase::SCI_LINEFROMPOSITION, static_cast<unsigned long>(end)));
    const int from = text->positionFromLineIndex(firstLine, 0);
    const int to = lastLine + 1 < text->lines() ? text->positionFromLineIndex(lastLine + 1, 0)
                                                : text->length();
    const auto* document = static_cast<const char*>(
        text->SendScintillaPtrResult(QsciScintillaBase::SCI_GETCHARACTERPOINTER));
    const std::string_view all(document + from, static_cast<std::size_t>(to - from));

    startStyling(from);
    std::size_t lineStart = 0;
    while (lineStart < all.size()) {
        const std::size_t newline = all.find('\n', lineStart);
        const std::size_t lineEnd = newline == std::string_view::npos ? all.size() : newline;
        const std::size_t next = newline == std::string_view::npos ? all.size() : newline + 1;
        styleLine(all.substr(lineStart, lineEnd - lineStart));
        if (lineEnd < next)
            setStyling(static_cast<int>(next - lineEnd), Default);
        lineStart = next;
    }
}

void PlutoLexer::styleLine(std::string_view line) {
    std::size_t styled = 0;
    for (const Span& span : spansOf(line)) {
        if (span.begin > styled)
            setStyling(static_cast<int>(span.begin - styled), Default);
        setStyling(static_cast<int>(span.length), span.style);
        styled = span.begin + span.length;
    }
    if (styled < line.size())
        setStyling(static_cast<int>(line.size() - styled), Default);
}

} // namespace rs::ui
