// SPDX-License-Identifier: GPL-3.0-or-later
#include "pl110/Pl110Lexer.h"

#include "pl110/Address.h"
#include "pl110/ProgramText.h"

#include <cctype>

namespace rs::ui {

namespace {

bool isWordCharacter(char c) {
    const auto u = static_cast<unsigned char>(c);
    return std::isalnum(u) || c == '_' || c == '.' || u >= 0x80;
}

} // namespace

Pl110Lexer::Pl110Lexer(QObject* parent) : PlutoLexer(parent) {}

const char* Pl110Lexer::language() const {
    return "PL110";
}

void Pl110Lexer::styleLine(std::string_view line) {
    const std::size_t comment = line.find(';');
    const std::string_view code = line.substr(0, comment);
    std::size_t at = 0;
    const auto style = [&](std::size_t length, Style kind) {
        setStyling(static_cast<int>(length), kind);
        at += length;
    };
    const std::size_t first = code.find_first_not_of(" \t");
    if (first != std::string_view::npos && code[first] == '$') {
        // "$target PL110", "$name Filling station": the directive, then its text.
        std::size_t word = first + 1;
        while (word < code.size() && isWordCharacter(code[word]))
            ++word;
        style(word, Directive);
        if (at < code.size())
            style(code.size() - at, DirectiveText);
    }
    while (at < code.size()) {
        const char c = code[at];
        if (c == ' ' || c == '\t') {
            std::size_t end = at;
            while (end < code.size() && (code[end] == ' ' || code[end] == '\t'))
                ++end;
            style(end - at, Default);
        } else if (c == '!') {
            style(1, Declaration);
        } else if (isWordCharacter(c)) {
            std::size_t end = at;
            while (end < code.size() && isWordCharacter(code[end]))
                ++end;
            const std::string_view word = code.substr(at, end - at);
            Style kind = Name;
            if (std::isdigit(static_cast<unsigned char>(c))) {
                kind = std::isdigit(static_cast<unsigned char>(word.back())) ? Number : Time;
            } else if (pl110::isKeyword(word)) {
                kind = Keyword;
            } else {
                switch (pl110::readAddress(word).shape) {
                case pl110::AddressReading::Shape::Address:
                    kind = Address;
                    break;
                case pl110::AddressReading::Shape::Malformed:
                    kind = Invalid;
                    break;
                case pl110::AddressReading::Shape::NotAnAddress:
                    break;
                }
            }
            style(end - at, kind);
        } else {
            style(1, Operator);
        }
    }
    if (comment != std::string_view::npos)
        style(line.size() - comment, Comment);
}

} // namespace rs::ui
