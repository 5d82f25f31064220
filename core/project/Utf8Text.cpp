// SPDX-License-Identifier: GPL-3.0-or-later
#include "Utf8Text.h"

#include <cstdint>

namespace rs::project {

std::optional<TextFault> findTextFault(std::string_view text) {
    std::size_t pos = 0;
    while (pos < text.size()) {
        const auto lead = static_cast<unsigned char>(text[pos]);
        if (lead == 0)
            return TextFault{pos, "NUL byte: not text"};
        if (lead < 0x80) {
            ++pos;
            continue;
        }
        const std::size_t length = (lead >> 5) == 0x6    ? 2
                                   : (lead >> 4) == 0xE  ? 3
                                   : (lead >> 3) == 0x1E ? 4
                                                         : 0;
        std::uint32_t code = lead & (length == 2 ? 0x1F : length == 3 ? 0x0F : 0x07);
        bool whole = length != 0 && pos + length <= text.size();
        for (std::size_t i = 1; whole && i < length; ++i) {
            whole = isUtf8Continuation(text[pos + i]);
            code = (code << 6) | (static_cast<unsigned char>(text[pos + i]) & 0x3F);
        }
        const std::uint32_t least = length == 2 ? 0x80 : length == 3 ? 0x800 : 0x10000;
        if (!whole || code < least || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF))
            return TextFault{pos, "invalid UTF-8: the file must be UTF-8 text"};
        pos += length;
    }
    return std::nullopt;
}

int characterColumn(std::string_view text, std::size_t offset) {
    int column = 1;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i)
        if (!isUtf8Continuation(text[i]))
            ++column;
    return column;
}

} // namespace rs::project
