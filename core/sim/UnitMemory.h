// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Address.h"

#include <array>
#include <cstdint>

namespace rs::sim {

// Every variable of one unit, sized for the largest unit type. Bits are bytes
// so the engine can point at them.
struct UnitMemory {
    static constexpr int kTerminals = 48; // I/Q/IQ numbers 0..47
    static constexpr int kMemories = 1024;
    static constexpr int kGlobalMemories = 28;
    static constexpr int kSystemMemories = 200;
    static constexpr int kRegisters = 150;
    static constexpr int kSystemRegisters = 100;
    static constexpr int kAnalogInputs = 8;
    static constexpr int kAsiSlaves = 64; // 0..31 A (or standard) slaves, 32..63 B slaves

    std::array<std::uint8_t, kTerminals> inputs{};
    std::array<std::uint8_t, kTerminals> outputs{};
    std::array<std::uint8_t, kMemories> memories{};
    std::array<std::uint8_t, kGlobalMemories> globalMemories{};
    std::array<std::uint8_t, kSystemMemories> systemMemories{};
    std::array<std::int16_t, kRegisters> registers{};
    std::array<std::int32_t, kSystemRegisters> systemRegisters{};
    std::array<std::int32_t, kAnalogInputs> analogInputs{};
    std::array<std::uint8_t, 32> asiSafeInputs{};
    std::array<std::array<std::uint8_t, 4>, kAsiSlaves> asiInputs{};
    std::array<std::array<std::uint8_t, 4>, kAsiSlaves> asiOutputs{};
    // The External Comm Blocks 0-3 (Gateway manual 4.5.2): data bits 0-63,
    // registers 0-7 and whether each block is received, as a gateway last
    // delivered them (Simulation::deliverPacket); the Ext_* blocks read them.
    static constexpr int kExternalBlocks = 4;
    std::array<std::uint16_t, kExternalBlocks> externalBits{};
    std::array<std::int16_t, 2 * kExternalBlocks> externalRegisters{};
    std::array<std::uint8_t, kExternalBlocks> externalValid{};
};

// Where a bit lives: a byte, a bit of a register, or an analogue input read as a bit.
struct BitRef {
    enum class Kind : std::uint8_t { None, Byte, RegisterBit, Analog } kind = Kind::None;
    std::uint8_t* byte = nullptr;
    std::int16_t* word = nullptr;
    std::int32_t* wide = nullptr;
    int bit = 0;

    bool read() const {
        switch (kind) {
        case Kind::Byte:
            return *byte != 0;
        case Kind::RegisterBit:
            return (static_cast<std::uint16_t>(*word) >> bit) & 1u;
        case Kind::Analog:
            return *wide != 0;
        case Kind::None:
            break;
        }
        return false;
    }
    void write(bool value) const {
        switch (kind) {
        case Kind::Byte:
            *byte = value;
            break;
        case Kind::RegisterBit: {
            auto bits = static_cast<std::uint16_t>(*word);
            bits = value ? static_cast<std::uint16_t>(bits | (1u << bit))
                         : static_cast<std::uint16_t>(bits & ~(1u << bit));
            *word = static_cast<std::int16_t>(bits);
            break;
        }
        case Kind::Analog:
        case Kind::None:
            break;
        }
    }
};

// Where a number lives: a 16-bit register, a double register (two of them),
// or a 32-bit value (system register, analogue input).
struct WordRef {
    enum class Kind : std::uint8_t { None, Register, Double, Wide } kind = Kind::None;
    std::int16_t* word = nullptr;
    std::int32_t* wide = nullptr;

    std::int64_t read() const {
        switch (kind) {
        case Kind::Register:
            return *word;
        case Kind::Double:
            return static_cast<std::int32_t>(
                static_cast<std::uint32_t>(static_cast<std::uint16_t>(word[0])) |
                static_cast<std::uint32_t>(static_cast<std::uint16_t>(word[1])) << 16);
        case Kind::Wide:
            return *wide;
        case Kind::None:
            break;
        }
        return 0;
    }
    // The value must already fit (see limits()).
    void write(std::int64_t value) const {
        switch (kind) {
        case Kind::Register:
            *word = static_cast<std::int16_t>(value);
            break;
        case Kind::Double: {
            const auto bits = static_cast<std::uint32_t>(static_cast<std::int32_t>(value));
            word[0] = static_cast<std::int16_t>(bits & 0xFFFF);
            word[1] = static_cast<std::int16_t>(bits >> 16);
            break;
        }
        case Kind::Wide:
            *wide = static_cast<std::int32_t>(value);
            break;
        case Kind::None:
            break;
        }
    }
    bool isDouble() const { return kind == Kind::Double; }
};

// Whether a variable of this kind reads as a number (R, DR and its halves,
// SR, IA) rather than as a bit, as scenarios, the GUI and the prover read it.
bool readsAsNumber(lang::AddressKind kind);

// The bit or word of `address` in `memory`; None when the memory has no such place.
BitRef bitRef(UnitMemory& memory, const lang::Address& address, bool forWriting);
WordRef wordRef(UnitMemory& memory, const lang::Address& address);

} // namespace rs::sim
