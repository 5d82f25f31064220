// SPDX-License-Identifier: GPL-3.0-or-later
#include "ImageCodec.h"

#include "IntelHex.h"
#include "SystemInstruction.h"
#include "project/AsiOptions.h"
#include "project/CanBusCycle.h"
#include "project/ExternalComm.h"
#include "project/Gateway.h"
#include "project/ProjectFile.h"

#include <zlib.h>

#include <optional>
#include <utility>

namespace rs::compiler {

namespace {

constexpr char kMagic[4] = {'R', 'S', 'I', 'M'};
constexpr std::uint16_t kVersion = 4;
constexpr std::size_t kInstructionSize = 28;
constexpr std::size_t kAddressSize = 6;
constexpr std::size_t kAsiSlaveSize = 13;
constexpr std::uint8_t kHasSource = 1;
// The included source was a project file, which no reader takes above this;
// a damaged length must not make the reader allocate gigabytes.
constexpr std::uint32_t kMaxIncludedSourceBytes = project::kMaxTextFileBytes;

class Writer {
public:
    // Room for all that will be written: grown as it goes, a large unit's
    // bytes were copied twice over (issue 23).
    explicit Writer(std::size_t room) { m_bytes.reserve(room); }
    void u8(std::uint8_t v) { m_bytes.push_back(v); }
    // Little-endian, appended at once.
    void u16(std::uint16_t v) {
        const std::uint8_t b[] = {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8)};
        append(b, sizeof b);
    }
    void u32(std::uint32_t v) {
        const std::uint8_t b[] = {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8),
                                  static_cast<std::uint8_t>(v >> 16),
                                  static_cast<std::uint8_t>(v >> 24)};
        append(b, sizeof b);
    }
    void bytes(std::string_view s) { m_bytes.insert(m_bytes.end(), s.begin(), s.end()); }
    void append(const std::uint8_t* data, std::size_t size) {
        m_bytes.insert(m_bytes.end(), data, data + size);
    }
    std::vector<std::uint8_t>& data() { return m_bytes; }
    std::vector<std::uint8_t> take() { return std::move(m_bytes); }

private:
    std::vector<std::uint8_t> m_bytes;
};

struct Truncated {};

class Reader {
public:
    explicit Reader(const std::vector<std::uint8_t>& bytes, std::size_t end)
        : m_bytes(bytes), m_end(end) {}
    std::uint8_t u8() {
        if (m_pos >= m_end)
            throw Truncated{};
        return m_bytes[m_pos++];
    }
    std::uint16_t u16() {
        std::uint16_t low = u8();
        return static_cast<std::uint16_t>(low | (u8() << 8));
    }
    std::uint32_t u32() {
        std::uint32_t low = u16();
        return low | (static_cast<std::uint32_t>(u16()) << 16);
    }
    std::string bytes(std::size_t n) {
        if (n > m_end - m_pos)
            throw Truncated{};
        std::string s(m_bytes.begin() + static_cast<std::ptrdiff_t>(m_pos),
                      m_bytes.begin() + static_cast<std::ptrdiff_t>(m_pos + n));
        m_pos += n;
        return s;
    }
    bool atEnd() const { return m_pos == m_end; }

private:
    const std::vector<std::uint8_t>& m_bytes;
    std::size_t m_end;
    std::size_t m_pos = 0;
};

std::string compress(const std::string& text) {
    uLongf size = compressBound(static_cast<uLong>(text.size()));
    std::string out(size, '\0');
    compress2(reinterpret_cast<Bytef*>(out.data()), &size,
              reinterpret_cast<const Bytef*>(text.data()), static_cast<uLong>(text.size()),
              Z_BEST_COMPRESSION);
    out.resize(size);
    return out;
}

bool uncompress(const std::string& packed, std::uint32_t length, std::string& out) {
    out.assign(length, '\0');
    uLongf size = length;
    return ::uncompress(reinterpret_cast<Bytef*>(out.data()), &size,
                        reinterpret_cast<const Bytef*>(packed.data()),
                        static_cast<uLong>(packed.size())) == Z_OK &&
           size == length;
}

void writeAddress(Writer& w, const lang::Address& address) {
    w.u8(static_cast<std::uint8_t>(address.kind));
    w.u8(static_cast<std::uint8_t>(address.unit));
    w.u8(static_cast<std::uint8_t>(static_cast<std::int8_t>(address.bit)));
    w.u8(address.asiB ? 1 : 0);
    w.u16(static_cast<std::uint16_t>(address.index));
}

// Nothing when the bytes are no address the encoder writes: an image must
// read back to the bytes it was read from.
std::optional<lang::Address> readAddress(Reader& r) {
    lang::Address address;
    address.kind = static_cast<lang::AddressKind>(r.u8());
    address.unit = r.u8();
    address.bit = static_cast<std::int8_t>(r.u8());
    const std::uint8_t asiB = r.u8();
    address.index = r.u16();
    if (asiB > 1)
        return std::nullopt;
    address.asiB = asiB != 0;
    return address;
}

// The parts of an instruction that decide what it does; where it came from
// follows them in the image.
// Sixteen bytes, little-endian, made apart and appended at once: images
// hold hundreds of thousands of instructions.
void writeInstructionAction(Writer& w, const Instruction& in) {
    const auto index = static_cast<std::uint16_t>(in.operand.index);
    const auto constant = static_cast<std::uint32_t>(in.constant);
    const std::uint8_t bytes[16] = {
        static_cast<std::uint8_t>(in.op),
        in.flags,
        in.aux,
        static_cast<std::uint8_t>(in.operand.kind),
        static_cast<std::uint8_t>(in.operand.unit),
        static_cast<std::uint8_t>(static_cast<std::int8_t>(in.operand.bit)),
        static_cast<std::uint8_t>(in.operand.asiB ? 1 : 0),
        0,
        static_cast<std::uint8_t>(index),
        static_cast<std::uint8_t>(index >> 8),
        static_cast<std::uint8_t>(in.slot),
        static_cast<std::uint8_t>(in.slot >> 8),
        static_cast<std::uint8_t>(constant),
        static_cast<std::uint8_t>(constant >> 8),
        static_cast<std::uint8_t>(constant >> 16),
        static_cast<std::uint8_t>(constant >> 24),
    };
    w.append(bytes, sizeof bytes);
}

void writeCounts(Writer& w, const UnitImage& image) {
    w.u16(image.timers);
    w.u16(image.edges);
    w.u16(static_cast<std::uint16_t>(image.steps.size()));
    for (const auto& step : image.steps) {
        w.u8(step.sequence);
        w.u8(step.step);
        w.u32(step.first);
        w.u32(step.count);
    }
}

void writeSetup(Writer& w, const UnitImage& image) {
    w.u32(static_cast<std::uint32_t>(image.terminals.size()));
    for (const auto& terminal : image.terminals) {
        w.u8(terminal.group);
        w.u8(static_cast<std::uint8_t>(terminal.kind));
        w.u16(terminal.number);
        w.u8(static_cast<std::uint8_t>(terminal.options.size()));
        for (const auto& option : terminal.options) {
            w.u16(static_cast<std::uint16_t>(option.size()));
            w.bytes(option);
        }
    }
    for (const auto* addresses : {&image.exported, &image.remanent}) {
        w.u32(static_cast<std::uint32_t>(addresses->size()));
        for (const auto& address : *addresses)
            writeAddress(w, address);
    }
}

void writeAsiSetup(Writer& w, const AsiSetup& asi) {
    w.u8(asi.mode);
    w.u8(asi.optimisation);
    w.u8(asi.slaveAddress);
    w.u8(static_cast<std::uint8_t>(asi.slaves.size()));
    for (const auto& slave : asi.slaves) {
        w.u8(slave.number);
        w.u8(slave.b ? 1 : 0);
        w.u8(slave.type);
        w.u8(slave.model);
        w.u8(slave.parameter);
        for (std::uint8_t digit : slave.profile)
            w.u8(digit);
        w.u8(slave.monitoring);
        w.u32(slave.timeLimitMs);
    }
}

void writeExternalComm(Writer& w, const std::vector<ExternalCommSetup>& blocks) {
    w.u8(static_cast<std::uint8_t>(blocks.size()));
    for (const auto& block : blocks) {
        w.u8(block.block);
        w.u8(block.gateway);
        w.u8(block.packet);
        w.u16(block.timeoutMs);
    }
}

// What a damaged image could put in the AS-i setup that the simulator must
// not meet; nothing when it is sound.
std::optional<std::string> asiSetupProblem(const AsiSetup& asi) {
    if (asi.mode > static_cast<std::uint8_t>(project::AsiMode::Unused) ||
        asi.optimisation >
            static_cast<std::uint8_t>(project::AsiOptimisation::DisturbanceImmunity) ||
        asi.slaveAddress > project::kAsiSlaveCount)
        return "the AS-i options are damaged";
    for (std::size_t i = 1; i < asi.slaves.size(); ++i) {
        const auto& before = asi.slaves[i - 1];
        const auto& slave = asi.slaves[i];
        if (std::pair(before.number, before.b) >= std::pair(slave.number, slave.b))
            return "the AS-i slaves of the image are out of order";
    }
    for (const auto& slave : asi.slaves) {
        const bool digits = slave.parameter <= 0xF && slave.profile[0] <= 0xF &&
                            slave.profile[1] <= 0xF && slave.profile[2] <= 0xF &&
                            slave.profile[3] <= 0xF;
        if (slave.number < 1 || slave.number > project::kAsiSlaveCount || slave.type == 0 ||
            slave.type > static_cast<std::uint8_t>(project::AsiSlaveType::PlutoAsSafeInput) ||
            slave.model >= project::asiSafeInputModels().size() || !digits ||
            slave.monitoring >
                static_cast<std::uint8_t>(project::ChannelMonitoring::SimultaneousDebounce) ||
            slave.timeLimitMs > project::kMaxAsiTimeLimitMs)
            return "AS-i slave " + std::to_string(slave.number) + (slave.b ? "B" : "") +
                   " of the image is damaged";
    }
    return std::nullopt;
}

std::size_t setupSize(const UnitImage& image) {
    std::size_t size = 3 * 4 + (image.exported.size() + image.remanent.size()) * kAddressSize + 4 +
                       image.asi.slaves.size() * kAsiSlaveSize + 2 + 1 +
                       image.externalComm.size() * 5;
    for (const auto& terminal : image.terminals) {
        size += 5;
        for (const auto& option : terminal.options)
            size += 2 + option.size();
    }
    return size;
}

// The engine runs a system instruction on the Arguments after it, as its
// table says: a damaged image must not make it read past the code or take a
// bit for a word.
std::optional<std::string> systemCallProblem(const std::vector<Instruction>& code) {
    for (std::size_t i = 0; i < code.size(); ++i) {
        const Instruction& in = code[i];
        if (in.op == Op::Argument)
            return "an operand of a system instruction without the instruction";
        if (in.op != Op::System)
            continue;
        const SystemInstruction* system = findSystemInstruction(in.aux);
        if (!system)
            return "unknown system instruction " + std::to_string(int(in.aux));
        const std::string name(system->name);
        if (in.slot != system->parameters.size())
            return "system instruction " + name + " takes " +
                   std::to_string(system->parameters.size()) + " operands, not " +
                   std::to_string(in.slot);
        if (in.slot > code.size() - i - 1)
            return "the code ends within the operands of system instruction " + name;
        for (std::size_t p = 0; p < system->parameters.size(); ++p) {
            const Instruction& argument = code[i + 1 + p];
            if (argument.op != Op::Argument || argument.aux != argumentRole(system->parameters[p]))
                return "operand " + std::to_string(p + 1) + " of system instruction " + name +
                       " is not what it takes";
        }
        i += in.slot;
    }
    return std::nullopt;
}

} // namespace

std::uint32_t crc32(std::string_view bytes) {
    return static_cast<std::uint32_t>(
        ::crc32(0L, reinterpret_cast<const Bytef*>(bytes.data()), static_cast<uInt>(bytes.size())));
}

std::uint32_t crc32(std::span<const std::uint8_t> bytes) {
    return crc32(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

namespace {

// At least the encoded image without its included source.
std::size_t boundWithoutSource(const UnitImage& image) {
    constexpr std::size_t kFixed = 4 + 2 + 4 * 1 + 4 + 4 + 2 + 3 * 2 + 4 + 4; // header, counts, crc
    constexpr std::size_t kStepSize = 1 + 1 + 4 + 4;
    return kFixed + image.projectName.size() + image.steps.size() * kStepSize +
           image.code.size() * kInstructionSize + setupSize(image);
}

} // namespace

std::size_t encodedSizeBound(const UnitImage& image) {
    std::size_t size = boundWithoutSource(image);
    if (!image.source.empty())
        size += 4 + 4 + ::compressBound(static_cast<uLong>(image.source.size()));
    return size;
}

std::vector<std::uint8_t> encodeImage(const UnitImage& image) {
    Writer w(encodedSizeBound(image));
    w.bytes(std::string_view(kMagic, 4));
    w.u16(kVersion);
    w.u8(image.station);
    w.u8(image.unitType);
    w.u8(image.instructionSet);
    w.u8(image.source.empty() ? 0 : kHasSource);
    w.u32(image.sourceCrc);
    w.u32(image.projectSignature);
    w.u16(static_cast<std::uint16_t>(image.projectName.size()));
    w.bytes(image.projectName);
    writeCounts(w, image);
    w.u32(static_cast<std::uint32_t>(image.code.size()));
    for (const auto& in : image.code) {
        writeInstructionAction(w, in);
        w.u32(in.line);
        w.u16(in.column);
        w.u16(in.element);
        w.u32(in.statement);
    }
    writeSetup(w, image);
    writeAsiSetup(w, image.asi);
    w.u16(image.canCycleMs);
    writeExternalComm(w, image.externalComm);
    if (!image.source.empty()) {
        const std::string packed = compress(image.source);
        w.u32(static_cast<std::uint32_t>(image.source.size()));
        w.u32(static_cast<std::uint32_t>(packed.size()));
        w.bytes(packed);
    }
    auto& bytes = w.data();
    w.u32(crc32(bytes));
    return std::move(bytes);
}

ImageResult decodeImage(const std::vector<std::uint8_t>& bytes) {
    if (bytes.size() < 8 || !std::equal(kMagic, kMagic + 4, bytes.begin()))
        return ImageError{0, 0, "not a Rungsmith image (it does not start with RSIM)"};
    const std::size_t end = bytes.size() - 4;
    const std::uint32_t stored = static_cast<std::uint32_t>(bytes[end]) |
                                 static_cast<std::uint32_t>(bytes[end + 1]) << 8 |
                                 static_cast<std::uint32_t>(bytes[end + 2]) << 16 |
                                 static_cast<std::uint32_t>(bytes[end + 3]) << 24;
    if (stored != crc32(std::span(bytes).first(end)))
        return ImageError{0, 0, "the image is damaged (its checksum does not match)"};
    Reader r(bytes, end);
    UnitImage image;
    try {
        r.bytes(4);
        if (std::uint16_t version = r.u16(); version != kVersion)
            return ImageError{0, 0,
                              "image format version " + std::to_string(version) +
                                  " is not supported (this Rungsmith reads version " +
                                  std::to_string(kVersion) + ")"};
        image.station = r.u8();
        image.unitType = r.u8();
        image.instructionSet = r.u8();
        const std::uint8_t flags = r.u8();
        image.sourceCrc = r.u32();
        image.projectSignature = r.u32();
        image.projectName = r.bytes(r.u16());
        image.timers = r.u16();
        image.edges = r.u16();
        image.steps.resize(r.u16());
        for (auto& step : image.steps) {
            step.sequence = r.u8();
            step.step = r.u8();
            step.first = r.u32();
            step.count = r.u32();
        }
        const std::uint32_t count = r.u32();
        if (count > (end / kInstructionSize))
            throw Truncated{};
        image.code.resize(count);
        for (auto& in : image.code) {
            in.op = static_cast<Op>(r.u8());
            in.flags = r.u8();
            in.aux = r.u8();
            in.operand.kind = static_cast<lang::AddressKind>(r.u8());
            in.operand.unit = r.u8();
            in.operand.bit = static_cast<std::int8_t>(r.u8());
            in.operand.asiB = r.u8() != 0;
            r.u8();
            in.operand.index = r.u16();
            in.slot = r.u16();
            in.constant = static_cast<std::int32_t>(r.u32());
            in.line = r.u32();
            in.column = r.u16();
            in.element = r.u16();
            in.statement = r.u32();
            if (in.op < Op::Rung || in.op > Op::Argument)
                return ImageError{0, 0, "unknown instruction " + std::to_string(int(in.op))};
            // The engine indexes its tables with these: a damaged image must
            // stop here, not there.
            if ((in.op == Op::Timer && in.aux > std::uint8_t(lang::TimerKind::OffDelay)) ||
                (in.op == Op::Compare && in.aux > std::uint8_t(lang::CompareOp::LessEqual)) ||
                (in.op == Op::Arith && in.aux > std::uint8_t(ArithOp::DivAB)))
                return ImageError{0, 0,
                                  "unknown variant " + std::to_string(int(in.aux)) +
                                      " of instruction " + std::to_string(int(in.op))};
        }
        if (auto problem = systemCallProblem(image.code))
            return ImageError{0, 0, *problem};
        for (const auto& step : image.steps)
            if (step.first > image.code.size() || step.count > image.code.size() - step.first)
                return ImageError{0, 0, "a step's code lies outside the image"};
        const std::uint32_t terminals = r.u32();
        if (terminals > end)
            throw Truncated{};
        image.terminals.resize(terminals);
        for (auto& terminal : image.terminals) {
            const std::uint8_t group = r.u8();
            if (group > TerminalSetup::Analogue)
                return ImageError{0, 0, "unknown terminal group " + std::to_string(int(group))};
            terminal.group = static_cast<TerminalSetup::Group>(group);
            terminal.kind = static_cast<lang::AddressKind>(r.u8());
            terminal.number = r.u16();
            terminal.options.resize(r.u8());
            for (auto& option : terminal.options)
                option = r.bytes(r.u16());
        }
        for (auto* addresses : {&image.exported, &image.remanent}) {
            const std::uint32_t count = r.u32();
            if (count > end / kAddressSize)
                throw Truncated{};
            addresses->resize(count);
            for (auto& address : *addresses) {
                const auto read = readAddress(r);
                if (!read)
                    return ImageError{0, 0, "an exported or remanent variable is damaged"};
                address = *read;
            }
        }
        image.asi.mode = r.u8();
        image.asi.optimisation = r.u8();
        image.asi.slaveAddress = r.u8();
        image.asi.slaves.resize(r.u8());
        bool flagsSound = true; // the B flag is written as 0 or 1
        for (auto& slave : image.asi.slaves) {
            slave.number = r.u8();
            const std::uint8_t b = r.u8();
            flagsSound = flagsSound && b <= 1;
            slave.b = b == 1;
            slave.type = r.u8();
            slave.model = r.u8();
            slave.parameter = r.u8();
            for (std::uint8_t& digit : slave.profile)
                digit = r.u8();
            slave.monitoring = r.u8();
            slave.timeLimitMs = r.u32();
        }
        if (!flagsSound)
            return ImageError{0, 0, "the AS-i options are damaged"};
        if (auto problem = asiSetupProblem(image.asi))
            return ImageError{0, 0, *problem};
        image.canCycleMs = r.u16();
        if (image.canCycleMs > project::kMaxCanCycleMs)
            return ImageError{0, 0, "the CAN bus cycle time is damaged"};
        image.externalComm.resize(r.u8());
        int lastBlock = -1;
        for (auto& block : image.externalComm) {
            block.block = r.u8();
            block.gateway = r.u8();
            block.packet = r.u8();
            block.timeoutMs = r.u16();
            if (block.block <= lastBlock || block.block >= project::kExternalCommBlocks ||
                block.gateway >= project::kGatewayNodes ||
                block.packet >= project::kToPlutoPackets ||
                block.timeoutMs > project::kMaxExternalTimeoutMs)
                return ImageError{0, 0, "the External communication setting is damaged"};
            lastBlock = block.block;
        }
        if (flags & kHasSource) {
            const std::uint32_t length = r.u32();
            if (length > kMaxIncludedSourceBytes)
                return ImageError{0, 0, "the included source code is larger than 64 MB"};
            const std::string packed = r.bytes(r.u32());
            if (!uncompress(packed, length, image.source))
                return ImageError{0, 0, "the included source code cannot be unpacked"};
        }
        if (!r.atEnd())
            return ImageError{0, 0, "unexpected bytes after the image"};
    } catch (const Truncated&) {
        return ImageError{0, 0, "the image is truncated"};
    }
    return image;
}

std::vector<std::uint8_t> behaviourBytes(const UnitImage& image) {
    Writer w(boundWithoutSource(image)); // more than enough: no places either
    w.u8(image.station);
    w.u8(image.unitType);
    w.u8(image.instructionSet);
    writeCounts(w, image);
    w.u32(static_cast<std::uint32_t>(image.code.size()));
    for (const auto& in : image.code)
        writeInstructionAction(w, in);
    writeSetup(w, image);
    // Only when set: the signature of every unit without AS-i options stays
    // what it was before images carried them, and so do validated versions.
    if (!(image.asi == AsiSetup{}))
        writeAsiSetup(w, image.asi);
    if (image.canCycleMs)
        w.u16(image.canCycleMs);
    if (!image.externalComm.empty())
        writeExternalComm(w, image.externalComm);
    return w.take(); // not copied: a large project's units are 10 MB of them
}

namespace {

std::vector<HexSegment> hpsSegments(const std::vector<UnitImage>& images) {
    std::vector<HexSegment> segments;
    for (const auto& image : images)
        segments.push_back({image.station * kHpsStationStride, encodeImage(image)});
    return segments;
}

} // namespace

std::string writeHps(const std::vector<UnitImage>& images) {
    return writeIntelHex(hpsSegments(images));
}

void writeHps(const std::vector<UnitImage>& images, const project::TextSink& sink) {
    writeIntelHex(hpsSegments(images), sink);
}

HpsResult readHps(std::string_view text) {
    HexReadResult hex = readIntelHex(text);
    if (hex.error)
        return ImageError{hex.error->line, hex.error->column, hex.error->message};
    std::vector<UnitImage> images;
    for (const auto& segment : hex.segments) {
        if (segment.address % kHpsStationStride != 0)
            return ImageError{0, 0, "data at an address where no unit's image starts"};
        ImageResult image = decodeImage(segment.bytes);
        if (auto* error = std::get_if<ImageError>(&image)) {
            error->message = "unit " + std::to_string(segment.address / kHpsStationStride) + ": " +
                             error->message;
            return *error;
        }
        auto& unit = std::get<UnitImage>(image);
        if (unit.station * kHpsStationStride != segment.address)
            return ImageError{
                0, 0,
                "the image of unit " + std::to_string(unit.station) + " is stored where unit " +
                    std::to_string(segment.address / kHpsStationStride) + "'s belongs"};
        images.push_back(std::move(unit));
    }
    if (images.empty())
        return ImageError{0, 0, "the file holds no unit image"};
    return images;
}

} // namespace rs::compiler
