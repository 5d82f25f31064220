// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Area.h"

#include <compare>
#include <cstdint>
#include <string>
#include <string_view>

namespace rs::pl110 {

enum class Width : std::uint8_t { Bit, Word, Double };

// A word holds a signed 16-bit value.
inline constexpr std::int32_t kWordMin = -32768;
inline constexpr std::int32_t kWordMax = 32767;

// One place in the PL110's memory: a numbered bit (I3, T2), a bit of a word
// (V3.4, SM0.1), a word (VW3, AI1, T2 as a value) or a double word (VD0).
struct Address {
    Area area = Area::Input;
    Width width = Width::Bit;
    int number = 0;
    int bit = -1; // bitsOfWords areas only

    friend auto operator<=>(const Address&, const Address&) = default;
};

// Reading a word such as "q3", "VW10", "sm0.1", "VD2".
struct AddressReading {
    enum class Shape { NotAnAddress, Address, Malformed } shape = Shape::NotAnAddress;
    Address address;
    std::string error; // Malformed: why, e.g. "I0 is out of range: I1-I256"
};

// Case-insensitive. A timer or counter number reads as its contact (Width::Bit);
// where a word is wanted, asWord gives its value.
AddressReading readAddress(std::string_view word);

// T2 and C2 name a contact and a value; every other address is what it reads as.
Address asWord(Address address);

// Canonical spelling, upper case: "Q3", "VW10", "SM0.1", "VD2".
std::string toString(const Address& address);

// Where the value lives in the engine's memory: the word index within its
// area, and the bit in that word (-1 for a whole word or the first of a double).
struct MemoryPlace {
    int word = 0;
    int bit = -1;
};
MemoryPlace memoryPlace(const Address& address);

} // namespace rs::pl110
