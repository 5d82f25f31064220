// SPDX-License-Identifier: GPL-3.0-or-later
#include "IntelHex.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <iterator>
#include <map>
#include <span>
#include <stdexcept>
#include <utility>

namespace rs::compiler {

namespace {

constexpr std::uint64_t addressSpace = std::uint64_t{1} << 32;
constexpr std::size_t bytesPerRecord = 16;

enum RecordType : std::uint8_t {
    Data = 0x00,
    EndOfFile = 0x01,
    ExtendedSegmentAddress = 0x02,
    StartSegmentAddress = 0x03,
    ExtendedLinearAddress = 0x04,
    StartLinearAddress = 0x05,
};

// Record columns: ':' is 1, the byte count 2-3, the address 4-7, the type 8-9.
constexpr int countColumn = 2;
constexpr int addressColumn = 4;
constexpr int typeColumn = 8;

void appendHexByte(std::string& out, std::uint8_t value) {
    constexpr char digits[] = "0123456789ABCDEF";
    out += digits[value >> 4];
    out += digits[value & 0x0F];
}

// "0x3A", the form of bytes in messages.
std::string byteText(std::uint8_t value) {
    std::string text = "0x";
    appendHexByte(text, value);
    return text;
}

std::string addressText(std::uint32_t value) {
    std::string text = "0x";
    for (int shift = 24; shift >= 0; shift -= 8)
        appendHexByte(text, static_cast<std::uint8_t>(value >> shift));
    return text;
}

// The two digits of every byte, "000102...FF": a record's bytes are written
// two characters at a time.
constexpr std::array<char, 512> kHexPairs = [] {
    constexpr char digits[] = "0123456789ABCDEF";
    std::array<char, 512> pairs{};
    for (int value = 0; value < 256; ++value) {
        pairs[2 * value] = digits[value >> 4];
        pairs[2 * value + 1] = digits[value & 0x0F];
    }
    return pairs;
}();

void appendRecord(std::string& out, RecordType type, std::uint16_t offset,
                  std::span<const std::uint8_t> data) {
    // Made in a buffer and appended once: a large image has hundreds of
    // thousands of records, and a string grown a character at a time was a
    // tenth of `compile` (docs/performance.md).
    char record[1 + 2 * (4 + 255 + 1) + 1];
    std::size_t length = 0;
    auto put = [&](std::uint8_t value) {
        std::memcpy(record + length, kHexPairs.data() + 2 * value, 2);
        length += 2;
    };
    const auto count = static_cast<std::uint8_t>(data.size());
    const auto offsetHigh = static_cast<std::uint8_t>(offset >> 8);
    const auto offsetLow = static_cast<std::uint8_t>(offset & 0xFF);
    std::uint8_t sum = count + offsetHigh + offsetLow + type;
    record[length++] = ':';
    put(count);
    put(offsetHigh);
    put(offsetLow);
    put(type);
    for (std::uint8_t byte : data) {
        put(byte);
        sum += byte;
    }
    put(static_cast<std::uint8_t>(-sum));
    record[length++] = '\n';
    out.append(record, length);
}

void checkWritable(const std::vector<HexSegment>& segments) {
    std::vector<std::pair<std::uint64_t, std::uint64_t>> ranges; // [begin, end)
    for (const auto& segment : segments) {
        if (segment.bytes.empty())
            continue;
        const std::uint64_t end = std::uint64_t{segment.address} + segment.bytes.size();
        if (end > addressSpace)
            throw std::invalid_argument("Intel HEX segment at " + addressText(segment.address) +
                                        " runs past the 4 GiB address space");
        ranges.emplace_back(segment.address, end);
    }
    std::sort(ranges.begin(), ranges.end());
    for (std::size_t i = 1; i < ranges.size(); ++i) {
        if (ranges[i].first < ranges[i - 1].second)
            throw std::invalid_argument("Intel HEX segments overlap at " +
                                        addressText(static_cast<std::uint32_t>(ranges[i].first)));
    }
}

int hexValue(char c) {
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    return -1;
}

std::string characterText(char c) {
    if (c >= 0x20 && c < 0x7F)
        return std::string("'") + c + "'";
    return "byte " + byteText(static_cast<std::uint8_t>(c));
}

struct Record {
    std::uint8_t type = 0;
    std::uint16_t offset = 0;
    std::vector<std::uint8_t> data;
};

struct RecordError {
    int column = 0;
    std::string message;
};

std::size_t expectedDataLength(std::uint8_t type) {
    switch (type) {
    case EndOfFile:
        return 0;
    case ExtendedSegmentAddress:
    case ExtendedLinearAddress:
        return 2;
    default: // the start address records
        return 4;
    }
}

std::string recordName(std::uint8_t type) {
    switch (type) {
    case EndOfFile:
        return "end-of-file record";
    case ExtendedSegmentAddress:
        return "extended segment address record";
    case StartSegmentAddress:
        return "start segment address record";
    case ExtendedLinearAddress:
        return "extended linear address record";
    default:
        return "start linear address record";
    }
}

// Checks one line's syntax, byte count and checksum, in that order: a digit flipped anywhere
// but in the byte count is then always reported as a checksum error.
std::optional<RecordError> parseRecord(std::string_view line, Record& record) {
    if (line.empty())
        return RecordError{1, "empty line"};
    if (line.front() != ':')
        return RecordError{1, "a record must start with ':'"};
    for (std::size_t i = 1; i < line.size(); ++i) {
        if (hexValue(line[i]) < 0)
            return RecordError{static_cast<int>(i) + 1,
                               characterText(line[i]) + " is not a hex digit"};
    }
    const std::size_t digits = line.size() - 1;
    if (digits % 2 != 0)
        return RecordError{static_cast<int>(line.size()),
                           "odd number of hex digits (" + std::to_string(digits) + ")"};
    std::vector<std::uint8_t> bytes(digits / 2);
    for (std::size_t i = 0; i < bytes.size(); ++i)
        bytes[i] =
            static_cast<std::uint8_t>(hexValue(line[1 + 2 * i]) * 16 + hexValue(line[2 + 2 * i]));
    // Byte count, two address bytes, type, checksum.
    constexpr std::size_t frameLength = 5;
    if (bytes.size() < frameLength)
        return RecordError{static_cast<int>(line.size()) + 1,
                           "record too short: " + std::to_string(bytes.size()) +
                               " bytes, at least 5 needed"};
    const std::size_t dataLength = bytes.size() - frameLength;
    if (bytes[0] != dataLength)
        return RecordError{countColumn, "byte count " + byteText(bytes[0]) +
                                            " disagrees with the " + std::to_string(dataLength) +
                                            " data bytes on the line"};
    std::uint8_t sum = 0;
    for (std::size_t i = 0; i + 1 < bytes.size(); ++i)
        sum += bytes[i];
    const auto expected = static_cast<std::uint8_t>(-sum);
    if (bytes.back() != expected)
        return RecordError{static_cast<int>(line.size()) - 1,
                           "checksum is " + byteText(bytes.back()) + ", expected " +
                               byteText(expected)};
    const std::uint8_t type = bytes[3];
    if (type > StartLinearAddress)
        return RecordError{typeColumn, "unknown record type " + byteText(type)};
    if (type != Data && dataLength != expectedDataLength(type))
        return RecordError{countColumn, recordName(type) + " needs " +
                                            std::to_string(expectedDataLength(type)) +
                                            " data bytes, not " + std::to_string(dataLength)};
    record.type = type;
    record.offset = static_cast<std::uint16_t>(bytes[1] << 8 | bytes[2]);
    record.data.assign(bytes.begin() + 4, bytes.end() - 1);
    return std::nullopt;
}

// The data read so far, one entry per run of consecutive addresses of one record, keyed by
// address; kept apart until the end so that an overlap can name the line it came from.
struct Run {
    int line = 0;
    std::vector<std::uint8_t> bytes;
};
using Runs = std::map<std::uint32_t, Run>;

std::uint64_t endOf(const Runs::value_type& entry) {
    return std::uint64_t{entry.first} + entry.second.bytes.size();
}

// The address where [address, address + size) meets data already read, and its line.
std::optional<std::pair<std::uint32_t, int>> findOverlap(const Runs& runs, std::uint32_t address,
                                                         std::size_t size) {
    auto after = runs.upper_bound(address);
    if (after != runs.begin()) {
        auto before = std::prev(after);
        if (endOf(*before) > address)
            return std::pair{address, before->second.line};
    }
    if (after != runs.end() && after->first < std::uint64_t{address} + size)
        return std::pair{after->first, after->second.line};
    return std::nullopt;
}

std::vector<HexSegment> mergeRuns(Runs& runs) {
    std::vector<HexSegment> segments;
    for (auto& [address, run] : runs) {
        if (!segments.empty() &&
            std::uint64_t{segments.back().address} + segments.back().bytes.size() == address) {
            auto& bytes = segments.back().bytes;
            bytes.insert(bytes.end(), run.bytes.begin(), run.bytes.end());
        } else {
            segments.push_back({address, std::move(run.bytes)});
        }
    }
    return segments;
}

HexReadResult failure(int line, int column, std::string message) {
    return {{}, HexError{line, column, std::move(message)}};
}

} // namespace

std::string writeIntelHex(const std::vector<HexSegment>& segments) {
    std::string out;
    std::size_t bytes = 0;
    for (const auto& segment : segments)
        bytes += segment.bytes.size();
    // Room for every record's digits and frame, each segment's part-filled last record, and an
    // 04 record per page: never short, as a string that outgrows it doubles (issue 23).
    const std::size_t records = bytes / bytesPerRecord + segments.size() + 1;
    const std::size_t pages = bytes / 0x10000 + segments.size() + 1;
    out.reserve(bytes * 2 + records * 12 + pages * 17);
    writeIntelHex(segments, [&out](std::string_view piece) { out += piece; });
    return out;
}

void writeIntelHex(const std::vector<HexSegment>& segments, const project::TextSink& sink) {
    checkWritable(segments);
    constexpr std::size_t pieceBytes = 64 * 1024;
    std::string out;
    out.reserve(pieceBytes + 1 + 2 * (4 + 255 + 1) + 1);
    const auto handOn = [&] {
        if (out.size() >= pieceBytes) {
            sink(out);
            out.clear();
        }
    };
    // Readers start with the upper address bits 0, so page 0 needs no 04 record.
    std::uint32_t page = 0;
    for (const auto& segment : segments) {
        const std::span<const std::uint8_t> bytes(segment.bytes);
        for (std::size_t done = 0; done < bytes.size();) {
            const auto address = static_cast<std::uint32_t>(segment.address + done);
            if (address >> 16 != page) {
                page = address >> 16;
                const std::uint8_t pageBytes[] = {static_cast<std::uint8_t>(page >> 8),
                                                  static_cast<std::uint8_t>(page & 0xFF)};
                appendRecord(out, ExtendedLinearAddress, 0, pageBytes);
            }
            const std::size_t roomInPage = 0x10000 - (address & 0xFFFF);
            const std::size_t count = std::min({bytesPerRecord, bytes.size() - done, roomInPage});
            appendRecord(out, Data, static_cast<std::uint16_t>(address & 0xFFFF),
                         bytes.subspan(done, count));
            done += count;
            handOn();
        }
    }
    appendRecord(out, EndOfFile, 0, {});
    sink(out);
}

HexReadResult readIntelHex(std::string_view text) {
    Runs runs;
    std::uint32_t base = 0;
    bool segmentAddressing = false; // 02 was the last extended address record, not 04
    bool ended = false;
    int lineNumber = 0;
    for (std::size_t position = 0; position < text.size();) {
        ++lineNumber;
        const std::size_t newline = text.find('\n', position);
        std::string_view line = text.substr(position, newline - position);
        position = newline == std::string_view::npos ? text.size() : newline + 1;
        if (newline != std::string_view::npos && line.ends_with('\r'))
            line.remove_suffix(1);
        if (ended)
            return failure(lineNumber, 1, "text after the end-of-file record");

        Record record;
        if (auto error = parseRecord(line, record))
            return failure(lineNumber, error->column, std::move(error->message));

        switch (record.type) {
        case Data: {
            // Per the specification: with 02 the offset wraps within the 64 KiB segment, with 04
            // the address wraps at 4 GiB. Either way a record may become two runs.
            auto addressOf = [&](std::size_t i) -> std::uint32_t {
                const std::uint32_t offset = record.offset + static_cast<std::uint32_t>(i);
                return base + (segmentAddressing ? offset & 0xFFFF : offset);
            };
            for (std::size_t begin = 0, end = 0; begin < record.data.size(); begin = end) {
                const std::uint32_t start = addressOf(begin);
                end = begin + 1;
                while (end < record.data.size() &&
                       addressOf(end) == std::uint64_t{start} + (end - begin))
                    ++end;
                if (auto overlap = findOverlap(runs, start, end - begin))
                    return failure(lineNumber, addressColumn,
                                   "data at " + addressText(overlap->first) +
                                       " overlaps data from line " +
                                       std::to_string(overlap->second));
                runs[start] = {lineNumber,
                               {record.data.begin() + static_cast<std::ptrdiff_t>(begin),
                                record.data.begin() + static_cast<std::ptrdiff_t>(end)}};
            }
            break;
        }
        case EndOfFile:
            ended = true;
            break;
        case ExtendedSegmentAddress:
            base = static_cast<std::uint32_t>(record.data[0] << 8 | record.data[1]) << 4;
            segmentAddressing = true;
            break;
        case ExtendedLinearAddress:
            base = static_cast<std::uint32_t>(record.data[0] << 8 | record.data[1]) << 16;
            segmentAddressing = false;
            break;
        default: // start addresses mean nothing to an image loaded by the simulator
            break;
        }
    }
    if (!ended)
        return failure(lineNumber + 1, 1, "missing end-of-file record");
    return {mergeRuns(runs), std::nullopt};
}

} // namespace rs::compiler
