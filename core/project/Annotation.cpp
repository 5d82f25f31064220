// SPDX-License-Identifier: GPL-3.0-or-later
#include "Annotation.h"

namespace rs::project {

namespace {

bool isBareChar(char c) {
    return c != ' ' && c != '\t' && c != '"' && c != '=';
}

} // namespace

std::string Annotation::value(std::string_view key) const {
    for (const auto& [k, v] : attributes)
        if (k == key)
            return v;
    return {};
}

std::optional<Annotation> parseAnnotation(std::string_view text) {
    if (text.empty() || text[0] != '@')
        return std::nullopt;
    Annotation annotation;
    std::size_t pos = 1;
    auto fail = [&](std::string message) -> AnnotationError {
        return {static_cast<int>(pos), std::move(message)};
    };
    auto skipSpaces = [&] {
        while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\t'))
            ++pos;
    };
    auto bare = [&] {
        std::size_t start = pos;
        while (pos < text.size() && isBareChar(text[pos]))
            ++pos;
        return std::string(text.substr(start, pos - start));
    };
    annotation.kind = bare();
    if (annotation.kind.empty())
        return std::nullopt; // a lone '@' is an ordinary comment
    skipSpaces();
    while (pos < text.size()) {
        std::string word = bare();
        if (word.empty())
            throw fail("expected a word or key=\"value\"");
        if (pos < text.size() && text[pos] == '=') {
            ++pos;
            std::string value;
            if (pos < text.size() && text[pos] == '"') {
                ++pos;
                bool closed = false;
                while (pos < text.size()) {
                    char c = text[pos++];
                    if (c == '"') {
                        closed = true;
                        break;
                    }
                    if (c == '\\') {
                        if (pos >= text.size())
                            break;
                        char e = text[pos++];
                        value += e == 'n' ? '\n' : e == 'r' ? '\r' : e == 't' ? '\t' : e;
                    } else {
                        value += c;
                    }
                }
                if (!closed)
                    throw fail("unterminated quoted value for '" + word + "'");
            } else {
                value = bare();
            }
            annotation.attributes.emplace_back(std::move(word), std::move(value));
        } else {
            annotation.arguments.push_back(std::move(word));
        }
        if (pos < text.size() && text[pos] != ' ' && text[pos] != '\t')
            throw fail("expected a space before '" + std::string(1, text[pos]) + "'");
        skipSpaces();
    }
    return annotation;
}

std::string formatAnnotation(const Annotation& annotation) {
    std::string text = "@" + annotation.kind;
    for (const auto& argument : annotation.arguments)
        text += " " + argument;
    for (const auto& [key, value] : annotation.attributes) {
        text += " " + key + "=\"";
        for (char c : value) {
            if (c == '"' || c == '\\')
                text += '\\';
            // A record is one line: no line break may end it early.
            if (c == '\n')
                text += "\\n";
            else if (c == '\r')
                text += "\\r";
            else if (c == '\t')
                text += "\\t";
            else
                text += c;
        }
        text += '"';
    }
    return text;
}

std::optional<Annotation> annotationOn(const lang::Line& line) {
    const auto* comment = std::get_if<lang::CommentLine>(&line.body);
    if (!comment)
        return std::nullopt;
    try {
        return parseAnnotation(comment->text);
    } catch (const AnnotationError&) {
        return std::nullopt;
    }
}

} // namespace rs::project
