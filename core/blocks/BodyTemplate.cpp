// SPDX-License-Identifier: GPL-3.0-or-later
#include "BodyTemplate.h"

namespace rs::blocks {

namespace {

bool isNameCharacter(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
}

bool isContinuation(char c) {
    return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

} // namespace

ScannedLine scanPlaceholders(std::string_view line) {
    ScannedLine scanned;
    for (std::size_t i = 0; i < line.size(); ++i) {
        if (line[i] == '}') {
            scanned.fault = TemplateFault{i, "'}' without its '{'"};
            return scanned;
        }
        if (line[i] != '{')
            continue;
        Placeholder placeholder;
        placeholder.offset = i;
        std::size_t j = i + 1;
        if (j < line.size() && line[j] == '#') {
            placeholder.isPrivate = true;
            ++j;
        }
        const std::size_t nameStart = j;
        while (j < line.size() && isNameCharacter(line[j]))
            ++j;
        if (j >= line.size() || line[j] != '}') {
            scanned.fault = TemplateFault{
                j, j >= line.size() ? "placeholder without its closing '}'"
                                    : "a placeholder holds a pin name or '#' and a private name"};
            return scanned;
        }
        placeholder.name = std::string(line.substr(nameStart, j - nameStart));
        if (placeholder.name.empty()) {
            scanned.fault = TemplateFault{i, "empty placeholder"};
            return scanned;
        }
        placeholder.length = j + 1 - i;
        scanned.placeholders.push_back(std::move(placeholder));
        i = j;
    }
    return scanned;
}

SubstitutedLine substitute(std::string_view line, const PlaceholderValue& value) {
    SubstitutedLine result;
    std::size_t next = 0;
    const auto copy = [&](std::size_t from, std::size_t to) {
        for (std::size_t k = from; k < to; ++k) {
            result.text.push_back(line[k]);
            result.templateOffset.push_back(k);
        }
    };
    for (const Placeholder& placeholder : scanPlaceholders(line).placeholders) {
        copy(next, placeholder.offset);
        const std::string text = value(placeholder);
        result.text += text;
        result.templateOffset.insert(result.templateOffset.end(), text.size(), placeholder.offset);
        next = placeholder.offset + placeholder.length;
    }
    copy(next, line.size());
    return result;
}

std::size_t byteOffset(std::string_view text, int column) {
    int seen = 1;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (isContinuation(text[i]))
            continue;
        if (seen == column)
            return i;
        ++seen;
    }
    return text.size();
}

} // namespace rs::blocks
