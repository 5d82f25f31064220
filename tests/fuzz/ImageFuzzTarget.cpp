// SPDX-License-Identifier: GPL-3.0-or-later
#include "FuzzFailure.h"

#include "compiler/ImageCodec.h"
#include "compiler/IntelHex.h"

#include <cstdint>
#include <exception>
#include <string_view>
#include <vector>

namespace {

using rs::fuzz::fail;

// Intel HEX: what reads writes back, and that text reads as the same data.
void checkIntelHex(std::string_view text) {
    const rs::compiler::HexReadResult read = rs::compiler::readIntelHex(text);
    if (read.error)
        return;
    std::string written;
    try {
        written = rs::compiler::writeIntelHex(read.segments);
    } catch (const std::exception& error) {
        fail(error.what());
    }
    const rs::compiler::HexReadResult again = rs::compiler::readIntelHex(written);
    if (again.error || again.segments != read.segments)
        fail("Intel HEX written from read data does not read back the same");
}

// A .hps file: its images write back to text that reads as the same images,
// and writing is stable (the zlib stream of an included source may differ
// from the one read, so the first text need not be the input).
void checkHps(std::string_view text) {
    const rs::compiler::HpsResult read = rs::compiler::readHps(text);
    const auto* images = std::get_if<std::vector<rs::compiler::UnitImage>>(&read);
    if (!images)
        return;
    std::string written;
    try {
        written = rs::compiler::writeHps(*images);
    } catch (const std::exception& error) {
        fail(error.what());
    }
    const rs::compiler::HpsResult again = rs::compiler::readHps(written);
    const auto* reread = std::get_if<std::vector<rs::compiler::UnitImage>>(&again);
    if (!reread || *reread != *images)
        fail("a .hps written from read images does not read back the same");
    if (rs::compiler::writeHps(*reread) != written)
        fail("writing a .hps is not stable");
}

// The same bytes as one unit's image, without the Intel HEX around it.
void checkImage(const std::uint8_t* data, std::size_t size) {
    const std::vector<std::uint8_t> bytes(data, data + size);
    const rs::compiler::ImageResult decoded = rs::compiler::decodeImage(bytes);
    const auto* image = std::get_if<rs::compiler::UnitImage>(&decoded);
    if (!image)
        return;
    const std::vector<std::uint8_t> encoded = rs::compiler::encodeImage(*image);
    if (image->source.empty() && encoded != bytes)
        fail("an image without source does not encode to the bytes it was read from");
    const rs::compiler::ImageResult again = rs::compiler::decodeImage(encoded);
    const auto* reread = std::get_if<rs::compiler::UnitImage>(&again);
    if (!reread || *reread != *image)
        fail("an encoded image does not decode to itself");
}

} // namespace

// Any input: reading an image never crashes, and what reads writes back.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    checkIntelHex(text);
    checkHps(text);
    checkImage(data, size);
    return 0;
}
