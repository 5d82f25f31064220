// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Image.h"
#include "project/TextSink.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace rs::compiler {

// The bytes of an image (docs/image-format.md). Deterministic: the same image
// always gives the same bytes.
std::vector<std::uint8_t> encodeImage(const UnitImage& image);

// The parts of an image that decide what the unit does, in the image's own
// encoding: station, type, instruction set, counts, steps, each instruction
// without where it came from, and the I/O setup, exported and remanent
// variables. Names, the project CRC, the included source and each
// instruction's line, column, statement and element are left out.
std::vector<std::uint8_t> behaviourBytes(const UnitImage& image);

struct ImageError {
    int line = 0; // in the .hps text; 0 when the bytes themselves are wrong
    int column = 0;
    std::string message;
};

using ImageResult = std::variant<UnitImage, ImageError>;

ImageResult decodeImage(const std::vector<std::uint8_t>& bytes);

// A .hps file: the images of a project's units as Intel HEX, each unit's at
// its station number times kHpsStationStride.
inline constexpr std::uint32_t kHpsStationStride = 0x1000000;

// The largest image of one unit: what fits before the next station's address,
// 16 MiB, about 14,000 statements of 40 contacts or 130,000 ordinary ones.
// The manuals state no program memory size for any Pluto type, so this is the
// bound for all of them.
inline constexpr std::size_t kMaxUnitImageBytes = kHpsStationStride;

// At least encodeImage(image).size(), without encoding (and compressing the
// source): most programs are far below kMaxUnitImageBytes.
std::size_t encodedSizeBound(const UnitImage& image);

std::string writeHps(const std::vector<UnitImage>& images);
// The same text given to sink in pieces (writeIntelHex).
void writeHps(const std::vector<UnitImage>& images, const project::TextSink& sink);

using HpsResult = std::variant<std::vector<UnitImage>, ImageError>;
HpsResult readHps(std::string_view text);

// CRC-32 (IEEE 802.3, zlib's crc32).
std::uint32_t crc32(std::string_view bytes);
std::uint32_t crc32(std::span<const std::uint8_t> bytes);

} // namespace rs::compiler
