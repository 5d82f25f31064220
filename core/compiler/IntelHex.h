// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "project/TextSink.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// Intel HEX (Intel "Hexadecimal Object File Format Specification", Rev. A), the text form of the
// compiled unit images (.hps) that the loader reads back for the simulator.
namespace rs::compiler {

// One contiguous block of bytes at an address.
struct HexSegment {
    std::uint32_t address = 0;
    std::vector<std::uint8_t> bytes;

    friend bool operator==(const HexSegment&, const HexSegment&) = default;
};

// Data records (type 00) of up to 16 bytes, an extended linear address record (04) before the
// first record of each 64 KiB page other than page 0, and the end-of-file record (01). Upper-case
// hex digits, "\n" line ends. A record never crosses a 64 KiB boundary, so readers that wrap the
// 16-bit offset agree with those that do not. Segments are written in the order given; empty
// ones write nothing. Throws std::invalid_argument when segments overlap or one runs past 4 GiB,
// since such text could not be read back to the same bytes.
std::string writeIntelHex(const std::vector<HexSegment>& segments);

// The same text given to sink in pieces of about 64 KiB, so that a large image reaches its file
// without the whole text in memory. Throws, as above, before the first piece.
void writeIntelHex(const std::vector<HexSegment>& segments, const project::TextSink& sink);

// Where the text is wrong: 1-based line and column (in bytes), and what is wrong.
struct HexError {
    int line = 0;
    int column = 0;
    std::string message;

    friend bool operator==(const HexError&, const HexError&) = default;
};

// On success, the data sorted by address, with touching data merged into one segment.
// On error, no segments and the first error in the text.
struct HexReadResult {
    std::vector<HexSegment> segments;
    std::optional<HexError> error;
};

// Reads record types 00, 01, 02 (extended segment address), 04 (extended linear address); 03 and
// 05 (start address) are checked and ignored. Lines end in "\n" or "\r\n"; the last line may
// end the text without one. Upper- and lower-case hex digits are accepted. An empty line is an
// error, and so is any line after the end-of-file record. Addresses are formed as the
// specification says: with 02 the 16-bit offset wraps within its 64 KiB segment, with 04 the
// address wraps at 4 GiB. Data written twice to the same address is an error.
HexReadResult readIntelHex(std::string_view text);

} // namespace rs::compiler
