// SPDX-License-Identifier: GPL-3.0-or-later
#include "prove/PropertyLexer.h"

#include "lang/Address.h"
#include "lang/Lexer.h"
#include "prove/PropertyWords.h"

#include <cctype>

namespace rs::ui {

PropertyLexer::PropertyLexer(QObject* parent) : PlutoLexer(parent) {}

const char* PropertyLexer::language() const {
    return "Pluto properties";
}

void PropertyLexer::styleLine(std::string_view line) {
    const std::size_t comment = line.find_first_of(";#");
    const std::string_view code = line.substr(0, comment);
    std::size_t styled = 0;
    bool durationNext = false; // the word after `within` and `cycle`
    lang::Lexer lexer(code);
    for (lang::Token token = lexer.next();
         token.kind != lang::TokenKind::EndOfFile && token.kind != lang::TokenKind::EndOfLine;
         token = lexer.next()) {
        const auto begin = static_cast<std::size_t>(token.text.data() - code.data());
        Style style = Operator;
        const bool duration = durationNext;
        durationNext = false;
        switch (token.kind) {
        case lang::TokenKind::Word:
            if (duration) {
                style = Time;
            } else if (isPropertyKeyword(token.text)) {
                style = Keyword;
                durationNext = isDurationKeyword(token.text);
            } else if (std::isdigit(static_cast<unsigned char>(token.text.front()))) {
                style = Number;
            } else {
                switch (lang::readAddressWord(token.text).shape) {
                case lang::AddressWord::Shape::Variable:
                case lang::AddressWord::Shape::Step:
                    style = Address;
                    break;
                case lang::AddressWord::Shape::Malformed:
                    style = Invalid;
                    break;
                case lang::AddressWord::Shape::NotAnAddress:
                    style = Name;
                    break;
                }
            }
            break;
        case lang::TokenKind::Number:
            style = duration ? Time : Number;
            break;
        case lang::TokenKind::Time:
            style = Time;
            break;
        case lang::TokenKind::Invalid:
        case lang::TokenKind::Bang:
        case lang::TokenKind::Dollar:
            style = Invalid;
            break;
        default:
            break;
        }
        if (begin > styled)
            setStyling(static_cast<int>(begin - styled), Default);
        setStyling(static_cast<int>(token.text.size()), style);
        styled = begin + token.text.size();
    }
    if (styled < code.size())
        setStyling(static_cast<int>(code.size() - styled), Default);
    if (comment != std::string_view::npos)
        setStyling(static_cast<int>(line.size() - comment), Comment);
}

} // namespace rs::ui
