// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Image.h"

#include <cstdint>
#include <string>
#include <vector>

// Program signatures (cli.md, "Verbs for review, change control and project
// work"): figures that change exactly when what a unit does changes, so a
// reviewer can tell that the program on a machine is the one validated.
// Formatting, comments, network grouping, names and descriptions never reach
// them. They are CRC-32, not a cryptographic hash: the manual's seal marks a
// program as reviewed and guards against mistakes, not against forgery, and a
// CRC-32 is certain to change for any change within 32 consecutive bits, such
// as one operand or one option.
namespace rs::compiler {

struct UnitSignature {
    int station = 0;
    std::uint32_t value = 0;
    friend bool operator==(const UnitSignature&, const UnitSignature&) = default;
};

// CRC-32 of the image's behaviourBytes (ImageCodec.h).
std::uint32_t unitSignature(const UnitImage& image);

// CRC-32 over each unit's station (1 byte) and signature (4 bytes, little
// endian), in the order given, which is by station.
std::uint32_t projectSignature(const std::vector<UnitSignature>& units);

// Eight upper-case hexadecimal digits.
std::string signatureText(std::uint32_t signature);

} // namespace rs::compiler
