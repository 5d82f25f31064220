// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

// The project is one UTF-8 text file: what a reader takes from elsewhere
// (a CSV, a scenario) is checked before it can end up in one.
namespace rs::project {

struct TextFault {
    std::size_t offset = 0; // bytes into the text
    std::string message;
};

// The first NUL byte or malformed UTF-8 sequence (overlong forms, surrogates
// and values past U+10FFFF included); nothing when the text is clean.
std::optional<TextFault> findTextFault(std::string_view text);

// The 1-based character column of a byte offset in UTF-8 text.
int characterColumn(std::string_view text, std::size_t offset);

// True for the bytes that continue a UTF-8 sequence: they start no character.
inline bool isUtf8Continuation(char c) {
    return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

} // namespace rs::project
