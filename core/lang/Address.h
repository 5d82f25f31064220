// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <compare>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>

namespace rs::lang {

enum class AddressKind : std::uint8_t {
    None,
    Input,              // Iu.n
    Output,             // Qu.n
    InputOutput,        // IQu.n, illuminated push button
    AnalogInput,        // IAu.n
    Memory,             // Mu.n
    GlobalMemory,       // GMu.n
    SystemMemory,       // SMu.n
    Register,           // Ru.n
    RegisterBit,        // Ru.n.b
    DoubleRegister,     // DRu.n
    DoubleRegisterLow,  // DRu.n.Lo
    DoubleRegisterHigh, // DRu.n.Hi
    SystemRegister,     // SRu.n
    AsiInput,           // ASiu.x (safe), ASiu.x.y, ASiu.xB.y
    AsiOutput,          // ASqu.x.y, ASqu.xB.y
    Sequence,           // Su.s, as in R(Su.s)
};

// One variable of one unit, as the language addresses it. Made as
// Address{kind, unit, index[, bit[, asiB]]}. The two one-byte fields lie
// together (16 bytes, not 20: every operand of a syntax tree holds one,
// issue 23); addresses still order by kind, unit, index, bit, then asiB.
struct Address {
    AddressKind kind = AddressKind::None;
    bool asiB = false; // AS-i B slave ("ASi0.3B.1")
    int unit = 0;
    int index = 0;
    int bit = -1; // register bit, or AS-i slave bit 1..4; -1 when absent

    constexpr Address() = default;
    constexpr Address(AddressKind kind, int unit = 0, int index = 0, int bit = -1,
                      bool asiB = false)
        : kind(kind), asiB(asiB), unit(unit), index(index), bit(bit) {}

    bool valid() const { return kind != AddressKind::None; }
    // IA inputs are both: an ordinary failsafe input, or an analogue or counter value.
    bool isBit() const;  // usable as a contact or a coil
    bool isWord() const; // usable in comparisons and arithmetic

    friend bool operator==(const Address&, const Address&) = default;
    friend std::strong_ordering operator<=>(const Address& a, const Address& b) {
        return std::tie(a.kind, a.unit, a.index, a.bit, a.asiB) <=>
               std::tie(b.kind, b.unit, b.index, b.bit, b.asiB);
    }
};

// A step header "Su.s_n".
struct StepAddress {
    int unit = 0;
    int sequence = 0;
    int step = 0;
    friend bool operator==(const StepAddress&, const StepAddress&) = default;
};

// The word as written was shaped like an address but is not one.
struct AddressError {
    std::string message;
};

// Result of reading a word such as "q0.10", "DR0.4.Lo", "ASi1.3B.2" or "s0.1_22".
struct AddressWord {
    enum class Shape { NotAnAddress, Variable, Step, Malformed } shape = Shape::NotAnAddress;
    Address address;
    StepAddress step;
    std::string error;
};

// Case-insensitive; leading zeros allowed.
AddressWord readAddressWord(std::string_view word);

// Canonical spelling: upper-case prefix ("Q0.10"), manual spellings for AS-i
// and double-register halves ("ASi1.3B.2", "DR0.4.Lo").
std::string toString(const Address& address);
std::string toString(const StepAddress& step);

// Prefix as the manuals write it, e.g. "GM" or "ASi".
std::string_view addressPrefix(AddressKind kind);

} // namespace rs::lang

// For hashed sets of addresses: every field, in one word.
namespace std {
template <> struct hash<rs::lang::Address> {
    size_t operator()(const rs::lang::Address& a) const noexcept {
        const auto field = [](int value, int shift) {
            return static_cast<uint64_t>(static_cast<uint32_t>(value)) << shift;
        };
        return hash<uint64_t>{}(field(static_cast<int>(a.kind), 56) ^ field(a.unit, 48) ^
                                field(a.index, 16) ^ field(a.bit + 1, 4) ^ (a.asiB ? 1U : 0U));
    }
};
} // namespace std
