// SPDX-License-Identifier: GPL-3.0-or-later
#include "lang/Address.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using namespace rs::lang;

namespace {

std::string canonical(std::string_view word) {
    AddressWord read = readAddressWord(word);
    if (read.shape == AddressWord::Shape::Step)
        return toString(read.step);
    if (read.shape != AddressWord::Shape::Variable)
        return "<" + read.error + ">";
    return toString(read.address);
}

} // namespace

TEST(Address, EveryOperandKindReadsAndPrintsCanonically) {
    EXPECT_EQ(canonical("q0.2"), "Q0.2");
    EXPECT_EQ(canonical("Q10.0001"), "Q10.1");
    EXPECT_EQ(canonical("i0.00"), "I0.0");
    EXPECT_EQ(canonical("iq0.14"), "IQ0.14");
    EXPECT_EQ(canonical("ia0.3"), "IA0.3");
    EXPECT_EQ(canonical("m7.1"), "M7.1");
    EXPECT_EQ(canonical("gm31.11"), "GM31.11");
    EXPECT_EQ(canonical("sm0.9"), "SM0.9");
    EXPECT_EQ(canonical("r0.100"), "R0.100");
    EXPECT_EQ(canonical("r0.100.15"), "R0.100.15");
    EXPECT_EQ(canonical("dr0.4"), "DR0.4");
    EXPECT_EQ(canonical("dr0.4.lo"), "DR0.4.Lo");
    EXPECT_EQ(canonical("DR0.4.HI"), "DR0.4.Hi");
    EXPECT_EQ(canonical("sr0.43"), "SR0.43");
    EXPECT_EQ(canonical("asi0.31"), "ASi0.31");
    EXPECT_EQ(canonical("ASI1.2.4"), "ASi1.2.4");
    EXPECT_EQ(canonical("asi1.2b.4"), "ASi1.2B.4");
    EXPECT_EQ(canonical("asq31.31B.1"), "ASq31.31B.1");
    EXPECT_EQ(canonical("s0.2"), "S0.2");
    EXPECT_EQ(canonical("s0.1_00"), "S0.1_0");
    EXPECT_EQ(canonical("S10.9_254"), "S10.9_254");
}

TEST(Address, KindsTellBitsFromWords) {
    EXPECT_TRUE(readAddressWord("Q0.1").address.isBit());
    EXPECT_TRUE(readAddressWord("R0.1.2").address.isBit());
    EXPECT_FALSE(readAddressWord("R0.1").address.isBit());
    EXPECT_TRUE(readAddressWord("R0.1").address.isWord());
    EXPECT_TRUE(readAddressWord("DR0.2.Hi").address.isWord());
    EXPECT_FALSE(readAddressWord("GM0.1").address.isWord());
    // An IA terminal is an ordinary input or an analogue/counter value.
    EXPECT_TRUE(readAddressWord("IA0.1").address.isBit());
    EXPECT_TRUE(readAddressWord("IA0.1").address.isWord());
}

TEST(Address, NamesAreNotAddresses) {
    EXPECT_EQ(readAddressWord("MuteSensor1").shape, AddressWord::Shape::NotAnAddress);
    EXPECT_EQ(readAddressWord("M10").shape, AddressWord::Shape::NotAnAddress);
    EXPECT_EQ(readAddressWord("Input.Lo").shape, AddressWord::Shape::NotAnAddress);
    EXPECT_EQ(readAddressWord("X0.1").shape, AddressWord::Shape::NotAnAddress);
}

TEST(Address, MalformedAddressesSayWhy) {
    EXPECT_EQ(canonical("Q0."), "<malformed address 'Q0.': expected a number after '.'>");
    EXPECT_EQ(canonical("Q0.1x"), "<malformed address 'Q0.1x'>");
    EXPECT_EQ(canonical("DR0.4.Mid"),
              "<malformed double register 'DR0.4.Mid': only .Lo or .Hi may follow>");
    EXPECT_EQ(canonical("ASq0.3"),
              "<malformed AS-i address 'ASq0.3': expected a bit number, as in ASq0.1.1>");
    EXPECT_EQ(canonical("S0.1_"),
              "<malformed step header 'S0.1_': expected S<unit>.<sequence>_<step>>");
    EXPECT_EQ(canonical("M0.9999999"), "<number too large in address 'M0.9999999'>");
}

// Sets and sorted lists of addresses (the image's exported variables, the
// unused names) order by kind, unit, index, bit, then the B slave, whatever
// the order of the fields in memory.
TEST(Address, OrdersByKindUnitIndexBitThenBSlave) {
    const std::vector<Address> ordered{
        {AddressKind::Input, 0, 7},
        {AddressKind::Input, 1, 0},
        {AddressKind::Output, 0, 0},
        {AddressKind::Register, 0, 3, -1},
        {AddressKind::Register, 0, 3, 0},
        {AddressKind::AsiInput, 0, 3, 1, false},
        {AddressKind::AsiInput, 0, 3, 1, true},
        {AddressKind::AsiInput, 0, 3, 2, false},
    };
    std::vector<Address> shuffled(ordered.rbegin(), ordered.rend());
    std::swap(shuffled[1], shuffled[5]);
    std::sort(shuffled.begin(), shuffled.end());
    EXPECT_EQ(shuffled, ordered);
    const Address input{AddressKind::Input, 2, 5};
    EXPECT_EQ(input.bit, -1);
    EXPECT_FALSE(input.asiB);
    EXPECT_EQ(toString(input), "I2.5");
}
