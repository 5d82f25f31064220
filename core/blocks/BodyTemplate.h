// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// A block's body is Pluto text with placeholders: {Pin} for a pin, {#name}
// for a private variable. Braces and '#' appear nowhere in the language
// (language.md), so a placeholder can never be read as Pluto, and an
// unsubstituted one can never pass as a program.
namespace rs::blocks {

struct Placeholder {
    std::string name; // without the braces and '#'
    bool isPrivate = false;
    std::size_t offset = 0; // bytes into the line, at '{'
    std::size_t length = 0; // bytes, braces included
};

struct TemplateFault {
    std::size_t offset = 0; // bytes into the line
    std::string message;
};

struct ScannedLine {
    std::vector<Placeholder> placeholders;
    std::optional<TemplateFault> fault;
};

// Every placeholder of one body line, or the first malformed one.
ScannedLine scanPlaceholders(std::string_view line);

// A line with every placeholder replaced, and for each byte of the result
// the byte of the template it came from, so that a problem found in the
// substituted text is reported where the author wrote it.
struct SubstitutedLine {
    std::string text;
    std::vector<std::size_t> templateOffset;
};

using PlaceholderValue = std::function<std::string(const Placeholder&)>;

// The line must scan without a fault.
SubstitutedLine substitute(std::string_view line, const PlaceholderValue& value);

// The byte offset of a 1-based character column (the end when past it).
std::size_t byteOffset(std::string_view text, int column);

} // namespace rs::blocks
