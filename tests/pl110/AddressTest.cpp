// SPDX-License-Identifier: GPL-3.0-or-later
#include "pl110/Address.h"

#include <gtest/gtest.h>

namespace rs::pl110 {
namespace {

TEST(Pl110Address, ReadsEveryAreaAndPrintsItCanonically) {
    const std::pair<std::string_view, std::string_view> cases[] = {
        {"i1", "I1"},       {"Q256", "Q256"},     {"m128", "M128"},   {"b32", "B32"},
        {"t48", "T48"},     {"c16", "C16"},       {"v0.0", "V0.0"},   {"V349.15", "V349.15"},
        {"vw010", "VW10"},  {"vd348", "VD348"},   {"sm0.1", "SM0.1"}, {"SMW185", "SMW185"},
        {"smd20", "SMD20"}, {"ai4", "AI4"},       {"aq1", "AQ1"},     {"pt48", "PT48"},
        {"pv16", "PV16"},   {"eep999", "EEP999"},
    };
    for (const auto& [written, canonical] : cases) {
        const AddressReading reading = readAddress(written);
        ASSERT_EQ(reading.shape, AddressReading::Shape::Address)
            << written << ": " << reading.error;
        EXPECT_EQ(toString(reading.address), canonical);
        EXPECT_EQ(readAddress(canonical).address, reading.address);
    }
}

TEST(Pl110Address, SaysWhyAnAddressIsOutOfRange) {
    EXPECT_EQ(readAddress("I0").error, "I0 is out of range: I1-I256");
    EXPECT_EQ(readAddress("T49").error, "T49 is out of range: T1-T48");
    EXPECT_EQ(readAddress("VD349").error, "VD349 is out of range: VD0-VD348");
    EXPECT_EQ(readAddress("V3").error, "V3 needs a bit: V3.0-V3.15, or the word VW3");
    EXPECT_EQ(readAddress("V3.16").error, "bit 16 of V3 is out of range: bits are 0-15");
    EXPECT_EQ(readAddress("Q1.2").error, "Q has no bit access: write Q1");
    EXPECT_EQ(readAddress("AQ2").shape, AddressReading::Shape::Malformed);
}

TEST(Pl110Address, NamesAreNotAddresses) {
    for (std::string_view name : {"Motor", "Start", "Tank.Level", "Q", "VWx", "Bypass2"})
        EXPECT_EQ(readAddress(name).shape, AddressReading::Shape::NotAnAddress) << name;
}

TEST(Pl110Address, TimersAndCountersAreContactsOrValues) {
    const Address contact = readAddress("T3").address;
    EXPECT_EQ(contact.width, Width::Bit);
    EXPECT_EQ(asWord(contact).width, Width::Word);
    EXPECT_EQ(toString(asWord(contact)), "T3");
    EXPECT_EQ(asWord(readAddress("I3").address).width, Width::Bit); // only T and C have values
}

TEST(Pl110Address, BitsArePackedSixteenToAWordFromTheFirstNumber) {
    // "I20 is stored on bit no. 3 of word 2" (datasheet 2.1): word index 1 here.
    const MemoryPlace i20 = memoryPlace(readAddress("I20").address);
    EXPECT_EQ(i20.word, 1);
    EXPECT_EQ(i20.bit, 3);
    const MemoryPlace v = memoryPlace(readAddress("V10.4").address);
    EXPECT_EQ(v.word, 10);
    EXPECT_EQ(v.bit, 4);
    EXPECT_EQ(wordCount(Area::Input), 16);
    EXPECT_EQ(wordCount(Area::Bistable), 2);
    EXPECT_EQ(wordCount(Area::Variable), 350);
    EXPECT_EQ(wordCount(Area::Timer), 48);
}

} // namespace
} // namespace rs::pl110
