// SPDX-License-Identifier: GPL-3.0-or-later
#include "Signature.h"

#include "ImageCodec.h"

#include <cstdio>

namespace rs::compiler {

std::uint32_t unitSignature(const UnitImage& image) {
    return crc32(behaviourBytes(image));
}

std::uint32_t projectSignature(const std::vector<UnitSignature>& units) {
    std::string bytes;
    for (const auto& unit : units) {
        bytes.push_back(static_cast<char>(unit.station));
        for (int shift = 0; shift < 32; shift += 8)
            bytes.push_back(static_cast<char>((unit.value >> shift) & 0xFF));
    }
    return crc32(bytes);
}

std::string signatureText(std::uint32_t signature) {
    char text[9];
    std::snprintf(text, sizeof text, "%08X", static_cast<unsigned>(signature));
    return text;
}

} // namespace rs::compiler
