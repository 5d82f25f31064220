// SPDX-License-Identifier: GPL-3.0-or-later
#include "compiler/IntelHex.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>

using namespace rs::compiler;

namespace {

// The data a reader should return for segments: sorted, without empty ones, touching ones merged.
std::vector<HexSegment> normalized(std::vector<HexSegment> segments) {
    std::erase_if(segments, [](const HexSegment& s) { return s.bytes.empty(); });
    std::sort(segments.begin(), segments.end(),
              [](const HexSegment& a, const HexSegment& b) { return a.address < b.address; });
    std::vector<HexSegment> merged;
    for (auto& segment : segments) {
        if (!merged.empty() &&
            std::uint64_t{merged.back().address} + merged.back().bytes.size() == segment.address)
            merged.back().bytes.insert(merged.back().bytes.end(), segment.bytes.begin(),
                                       segment.bytes.end());
        else
            merged.push_back(std::move(segment));
    }
    return merged;
}

std::vector<HexSegment> readOk(std::string_view text) {
    HexReadResult result = readIntelHex(text);
    EXPECT_FALSE(result.error) << result.error->line << ":" << result.error->column << ": "
                               << result.error->message;
    return result.segments;
}

HexError readError(std::string_view text) {
    HexReadResult result = readIntelHex(text);
    EXPECT_TRUE(result.segments.empty());
    return result.error.value_or(HexError{0, 0, "<no error>"});
}

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    for (std::size_t begin = 0, end; begin < text.size(); begin = end + 1) {
        end = text.find('\n', begin);
        lines.push_back(text.substr(begin, end - begin));
    }
    return lines;
}

// The Intel HEX example published with the format's description: 64 bytes from 0x0100.
constexpr std::string_view publishedExample = ":10010000214601360121470136007EFE09D2190140\n"
                                              ":100110002146017E17C20001FF5F16002148011928\n"
                                              ":10012000194E79234623965778239EDA3F01B2CAA7\n"
                                              ":100130003F0156702B5E712B722B732146013421C7\n"
                                              ":00000001FF\n";

} // namespace

TEST(IntelHex, WritesTheRecordFromTheSpecification) {
    EXPECT_EQ(writeIntelHex({{0x0030, {0x02, 0x33, 0x7A}}}), ":0300300002337A1E\n"
                                                             ":00000001FF\n");
}

TEST(IntelHex, WritesNothingButEndOfFileForNoData) {
    EXPECT_EQ(writeIntelHex({}), ":00000001FF\n");
    EXPECT_EQ(writeIntelHex({{0x1234, {}}}), ":00000001FF\n");
}

TEST(IntelHex, WritesSixteenBytesARecord) {
    std::vector<std::uint8_t> bytes(17);
    for (std::size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = static_cast<std::uint8_t>(i);
    // 01+01+10+00+10 = 0x22, checksum 0x100-0x22 = 0xDE.
    EXPECT_EQ(writeIntelHex({{0x0100, bytes}}), ":10010000000102030405060708090A0B0C0D0E0F77\n"
                                                ":0101100010DE\n"
                                                ":00000001FF\n");
}

TEST(IntelHex, WritesAnExtendedLinearAddressAtA64KiBBoundary) {
    // 02+FF+FE+00+AA+BB = 0x364, checksum 0x9C; 02+04+01 = 0x07, checksum 0xF9.
    EXPECT_EQ(writeIntelHex({{0xFFFE, {0xAA, 0xBB, 0x11, 0x22}}}), ":02FFFE00AABB9C\n"
                                                                   ":020000040001F9\n"
                                                                   ":020000001122CB\n"
                                                                   ":00000001FF\n");
    // 01+FF+FF+00+C1 = 0x2C0, checksum 0x40.
    EXPECT_EQ(writeIntelHex({{0xFFFFFFFF, {0xC1}}}), ":02000004FFFFFC\n"
                                                     ":01FFFF00C140\n"
                                                     ":00000001FF\n");
}

TEST(IntelHex, WritesSegmentsInTheOrderGivenAndSwitchesPagesBack) {
    EXPECT_EQ(writeIntelHex({{0x10000, {0x10}}, {0x0000, {0x10}}}), ":020000040001F9\n"
                                                                    ":0100000010EF\n"
                                                                    ":020000040000FA\n"
                                                                    ":0100000010EF\n"
                                                                    ":00000001FF\n");
}

TEST(IntelHex, RefusesToWriteWhatCouldNotBeReadBack) {
    EXPECT_THROW(writeIntelHex({{0x10, {1, 2}}, {0x11, {3}}}), std::invalid_argument);
    EXPECT_THROW(writeIntelHex({{0x11, {3}}, {0x10, {1, 2}}}), std::invalid_argument);
    EXPECT_THROW(writeIntelHex({{0xFFFFFFFF, {1, 2}}}), std::invalid_argument);
    EXPECT_NO_THROW(writeIntelHex({{0x10, {1, 2}}, {0x12, {3}}, {0x11, {}}}));
}

// Written as made: a large image in pieces of about 64 KiB, each ending at a
// record's end, together the text of the whole.
TEST(IntelHex, WritesALargeImageInPiecesOfWholeRecords) {
    std::vector<HexSegment> segments{{0x1000000, std::vector<std::uint8_t>(300000, 0x5A)},
                                     {0x2000000, std::vector<std::uint8_t>(70000, 0xA5)}};
    std::vector<std::string> pieces;
    writeIntelHex(segments, [&](std::string_view piece) { pieces.emplace_back(piece); });
    ASSERT_GT(pieces.size(), 10u);
    std::string joined;
    for (const std::string& piece : pieces) {
        EXPECT_LE(piece.size(), 64 * 1024 + 44u);
        EXPECT_EQ(piece.back(), '\n');
        joined += piece;
    }
    const std::string whole = writeIntelHex(segments);
    EXPECT_EQ(joined, whole);
    EXPECT_LE(whole.capacity(), whole.size() + whole.size() / 50)
        << "the text was made in the room reserved for it, not a doubled string";
    EXPECT_THROW(writeIntelHex({{0x10, {1, 2}}, {0x11, {3}}},
                               [](std::string_view) { FAIL() << "nothing is written"; }),
                 std::invalid_argument);
}

TEST(IntelHex, ReadsAndRewritesThePublishedExample) {
    std::vector<HexSegment> segments = readOk(publishedExample);
    ASSERT_EQ(segments.size(), 1u);
    EXPECT_EQ(segments[0].address, 0x0100u);
    ASSERT_EQ(segments[0].bytes.size(), 64u);
    EXPECT_EQ(segments[0].bytes.front(), 0x21);
    EXPECT_EQ(segments[0].bytes.back(), 0x21);
    EXPECT_EQ(writeIntelHex(segments), publishedExample);
}

TEST(IntelHex, ReadsCrLfLowerCaseAndNoFinalNewline) {
    EXPECT_EQ(readOk(":0300300002337a1e\r\n:00000001ff"),
              (std::vector<HexSegment>{{0x30, {0x02, 0x33, 0x7A}}}));
    EXPECT_EQ(readOk(":0300300002337A1E\r\n:00000001FF\r\n"),
              (std::vector<HexSegment>{{0x30, {0x02, 0x33, 0x7A}}}));
}

TEST(IntelHex, MergesTouchingRecordsInAnyOrder) {
    EXPECT_EQ(readOk(":01001200B13C\n:02001000A1A2AB\n:0000000000\n:00000001FF\n"),
              (std::vector<HexSegment>{{0x10, {0xA1, 0xA2, 0xB1}}}));
    EXPECT_EQ(readOk(":01001300B13B\n:02001000A1A2AB\n:00000001FF\n"),
              (std::vector<HexSegment>{{0x10, {0xA1, 0xA2}}, {0x13, {0xB1}}}));
}

TEST(IntelHex, ExtendedSegmentAddressWrapsTheOffsetWithinItsSegment) {
    // Base 0x1000 * 16 = 0x10000; the second byte at offset 0x10000 wraps to 0x0000.
    EXPECT_EQ(readOk(":020000021000EC\n"
                     ":02FFFF00C1C27D\n"
                     ":0400000300003800C1\n"
                     ":040000050000CD002A\n"
                     ":00000001FF\n"),
              (std::vector<HexSegment>{{0x10000, {0xC2}}, {0x1FFFF, {0xC1}}}));
}

TEST(IntelHex, ExtendedLinearAddressCarriesAcross64KiBAndWrapsAt4GiB) {
    EXPECT_EQ(readOk(":02FFFF00C1C27D\n:00000001FF\n"),
              (std::vector<HexSegment>{{0xFFFF, {0xC1, 0xC2}}}));
    EXPECT_EQ(readOk(":02000004FFFFFC\n:02FFFF00C1C27D\n:00000001FF\n"),
              (std::vector<HexSegment>{{0x0000, {0xC2}}, {0xFFFFFFFF, {0xC1}}}));
    // A 04 record replaces the segment base of an earlier 02 record.
    EXPECT_EQ(readOk(":020000021000EC\n:020000040002F8\n:0100000010EF\n:00000001FF\n"),
              (std::vector<HexSegment>{{0x20000, {0x10}}}));
}

TEST(IntelHex, RejectsALineNotStartingWithAColon) {
    EXPECT_EQ(readError("0300300002337A1E\n:00000001FF\n"),
              (HexError{1, 1, "a record must start with ':'"}));
    EXPECT_EQ(readError(":0300300002337A1E\n :00000001FF\n"),
              (HexError{2, 1, "a record must start with ':'"}));
}

TEST(IntelHex, RejectsANonHexCharacterAtItsColumn) {
    EXPECT_EQ(readError(":0300300002337A1E\n:03003000G2337A1E\n:00000001FF\n"),
              (HexError{2, 10, "'G' is not a hex digit"}));
    EXPECT_EQ(readError(":0300300002337A1E \n:00000001FF\n"),
              (HexError{1, 18, "' ' is not a hex digit"}));
    // Only "\r\n" ends a line; a lone "\r" is part of it.
    EXPECT_EQ(readError(":00000001FF\r"), (HexError{1, 12, "byte 0x0D is not a hex digit"}));
}

TEST(IntelHex, RejectsAnOddNumberOfHexDigits) {
    EXPECT_EQ(readError(":0300300002337A1E0\n:00000001FF\n"),
              (HexError{1, 18, "odd number of hex digits (17)"}));
}

TEST(IntelHex, RejectsARecordTooShortForItsFrame) {
    EXPECT_EQ(readError(":00000001\n"),
              (HexError{1, 10, "record too short: 4 bytes, at least 5 needed"}));
    EXPECT_EQ(readError(":\n"), (HexError{1, 2, "record too short: 0 bytes, at least 5 needed"}));
}

TEST(IntelHex, RejectsAByteCountThatDisagreesWithTheLine) {
    EXPECT_EQ(readError(":0400300002337A1E\n:00000001FF\n"),
              (HexError{1, 2, "byte count 0x04 disagrees with the 3 data bytes on the line"}));
    EXPECT_EQ(readError(":0300300002337A\n:00000001FF\n"),
              (HexError{1, 2, "byte count 0x03 disagrees with the 2 data bytes on the line"}));
}

TEST(IntelHex, RejectsAWrongChecksum) {
    EXPECT_EQ(readError(":0300300002337A1E\n:0300300002337A1F\n:00000001FF\n"),
              (HexError{2, 16, "checksum is 0x1F, expected 0x1E"}));
    EXPECT_EQ(readError(":00000001FE\n"), (HexError{1, 10, "checksum is 0xFE, expected 0xFF"}));
}

TEST(IntelHex, RejectsAnUnknownRecordType) {
    EXPECT_EQ(readError(":00000006FA\n:00000001FF\n"),
              (HexError{1, 8, "unknown record type 0x06"}));
}

TEST(IntelHex, RejectsARecordOfTheWrongLengthForItsType) {
    EXPECT_EQ(readError(":020000010000FD\n"),
              (HexError{1, 2, "end-of-file record needs 0 data bytes, not 2"}));
    EXPECT_EQ(readError(":0100000212EB\n:00000001FF\n"),
              (HexError{1, 2, "extended segment address record needs 2 data bytes, not 1"}));
    EXPECT_EQ(readError(":0100000412E9\n:00000001FF\n"),
              (HexError{1, 2, "extended linear address record needs 2 data bytes, not 1"}));
    EXPECT_EQ(readError(":020000030000FB\n:00000001FF\n"),
              (HexError{1, 2, "start segment address record needs 4 data bytes, not 2"}));
    EXPECT_EQ(readError(":020000050000F9\n:00000001FF\n"),
              (HexError{1, 2, "start linear address record needs 4 data bytes, not 2"}));
}

TEST(IntelHex, RejectsAnEmptyLine) {
    EXPECT_EQ(readError(":0300300002337A1E\n\n:00000001FF\n"), (HexError{2, 1, "empty line"}));
    EXPECT_EQ(readError(":0300300002337A1E\r\n\r\n:00000001FF\r\n"),
              (HexError{2, 1, "empty line"}));
}

TEST(IntelHex, RejectsAnythingAfterTheEndOfFileRecord) {
    EXPECT_EQ(readError(":00000001FF\n:0300300002337A1E\n"),
              (HexError{2, 1, "text after the end-of-file record"}));
    EXPECT_EQ(readError(":00000001FF\n\n"), (HexError{2, 1, "text after the end-of-file record"}));
    EXPECT_EQ(readError(":00000001FF\n:00000001FF\n"),
              (HexError{2, 1, "text after the end-of-file record"}));
}

TEST(IntelHex, RejectsAMissingEndOfFileRecordOnTheLineAfterTheLast) {
    EXPECT_EQ(readError(""), (HexError{1, 1, "missing end-of-file record"}));
    EXPECT_EQ(readError(":0300300002337A1E\n"), (HexError{2, 1, "missing end-of-file record"}));
    EXPECT_EQ(readError(":0300300002337A1E\r\n:0000000000"),
              (HexError{3, 1, "missing end-of-file record"}));
}

TEST(IntelHex, RejectsOverlappingData) {
    EXPECT_EQ(readError(":02001000A1A2AB\n:01001100B13D\n:00000001FF\n"),
              (HexError{2, 4, "data at 0x00000011 overlaps data from line 1"}));
    EXPECT_EQ(readError(":01001100B13D\n:0100000010EF\n:02001000A1A2AB\n:00000001FF\n"),
              (HexError{3, 4, "data at 0x00000011 overlaps data from line 1"}));
    // 0x1000:0000 and 0x0001:0000 name the same byte.
    EXPECT_EQ(readError(":020000021000EC\n:0100000010EF\n:020000040001F9\n:0100000010EF\n"
                        ":00000001FF\n"),
              (HexError{4, 4, "data at 0x00010000 overlaps data from line 2"}));
}

TEST(IntelHex, EverySingleDigitChangeIsDetected) {
    const std::string valid = writeIntelHex({{0xFFF8, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}}});
    ASSERT_EQ(linesOf(valid).size(), 4u); // data, 04, data, end of file
    ASSERT_FALSE(readIntelHex(valid).error);
    const std::string_view digits = "0123456789ABCDEF";
    int lineNumber = 0;
    std::size_t lineStart = 0;
    for (const std::string& line : linesOf(valid)) {
        ++lineNumber;
        for (std::size_t i = 1; i < line.size(); ++i) {
            for (char digit : digits) {
                if (digit == line[i])
                    continue;
                std::string changed = valid;
                changed[lineStart + i] = digit;
                const HexError error = readError(changed);
                SCOPED_TRACE(changed);
                EXPECT_EQ(error.line, lineNumber);
                if (i <= 2) { // the byte count itself: the line's length disagrees first
                    EXPECT_EQ(error.column, 2);
                    EXPECT_TRUE(error.message.starts_with("byte count ")) << error.message;
                } else {
                    EXPECT_EQ(error.column, static_cast<int>(line.size()) - 1);
                    EXPECT_TRUE(error.message.starts_with("checksum is ")) << error.message;
                }
            }
        }
        lineStart += line.size() + 1;
    }
}

TEST(IntelHex, RandomBlocksRoundTrip) {
    constexpr std::size_t sizesOfInterest[] = {0, 1, 15, 16, 17, 65535, 65536, 70000};
    std::mt19937 random(20240611);
    auto below = [&](std::uint64_t n) {
        return std::uniform_int_distribution<std::uint64_t>(0, n - 1)(random);
    };
    for (int iteration = 0; iteration < 300; ++iteration) {
        // 1-4 blocks laid out upwards with gaps that are sometimes zero, so that blocks touch,
        // placed low, across a 64 KiB boundary or against the 4 GiB end, and written shuffled.
        std::vector<HexSegment> segments(1 + below(4));
        std::vector<std::uint64_t> gaps;
        std::uint64_t span = 0;
        for (auto& segment : segments) {
            segment.bytes.resize(below(2) ? sizesOfInterest[below(std::size(sizesOfInterest))]
                                          : below(300));
            for (auto& byte : segment.bytes)
                byte = static_cast<std::uint8_t>(random());
            gaps.push_back(below(3) ? 0 : below(100));
            span += segment.bytes.size() + gaps.back();
        }
        const std::uint64_t top = std::uint64_t{1} << 32;
        const std::uint64_t placements[] = {below(0x40000),
                                            (1 + below(0xFFFE)) * 0x10000 - below(40), top - span};
        std::uint64_t next = std::min(placements[below(3)], top - span);
        for (std::size_t i = 0; i < segments.size(); ++i) {
            segments[i].address = static_cast<std::uint32_t>(next);
            next += segments[i].bytes.size() + gaps[i];
        }
        const std::vector<HexSegment> expected = normalized(segments);
        std::shuffle(segments.begin(), segments.end(), random);
        SCOPED_TRACE(iteration);

        const std::string text = writeIntelHex(segments);
        std::string pieces;
        writeIntelHex(segments, [&](std::string_view piece) {
            ASSERT_LE(piece.size(), 64 * 1024 + 1 + 2 * (5 + 16u) + 1);
            pieces += piece;
        });
        ASSERT_EQ(pieces, text);
        for (const std::string& line : linesOf(text)) {
            ASSERT_LE(line.size(), 1 + 2 * (5 + 16u));
            ASSERT_EQ(line.find_first_not_of("0123456789ABCDEF", 1), std::string::npos) << line;
        }
        ASSERT_EQ(text.back(), '\n');

        HexReadResult result = readIntelHex(text);
        ASSERT_FALSE(result.error) << result.error->message;
        EXPECT_EQ(result.segments, expected);
    }
}
