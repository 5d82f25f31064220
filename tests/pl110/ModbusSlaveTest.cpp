// SPDX-License-Identifier: GPL-3.0-or-later
#include "pl110/ModbusSlave.h"

#include <gtest/gtest.h>

namespace rs::pl110 {
namespace {

using Bytes = std::vector<std::uint8_t>;

Address modbusAddress(std::string_view word) {
    return readAddress(word).address;
}

TEST(Pl110Modbus, ReadsOutputBitsAndWordsWhereTheDatasheetMapsThem) {
    Memory memory;
    memory.setBit(modbusAddress("Q1"), true);
    memory.setBit(modbusAddress("Q3"), true);
    memory.setBit(modbusAddress("Q16"), true);
    memory.setValue(modbusAddress("VW0"), -2);
    memory.setValue(modbusAddress("VW1"), 300);
    // Bits 2400.. are Q1..: Q1 and Q3 on.
    EXPECT_EQ(answerRequest(memory, Bytes{1, 0x09, 0x60, 0, 8}), (Bytes{1, 1, 0x05}));
    // Word 150 packs Q1..Q16, bit 0 = Q1.
    EXPECT_EQ(answerRequest(memory, Bytes{3, 0, 150, 0, 1}), (Bytes{3, 2, 0x80, 0x05}));
    // Words 2000.. are VW0..; function 4 reads the same map.
    EXPECT_EQ(answerRequest(memory, Bytes{4, 0x07, 0xD0, 0, 2}),
              (Bytes{4, 4, 0xFF, 0xFE, 0x01, 0x2C}));
}

TEST(Pl110Modbus, TimerContactsArePackedAndValuesAreWords) {
    Memory memory;
    memory.setBit(modbusAddress("T2"), true);
    memory.setBit(modbusAddress("T17"), true);
    memory.setValue(asWord(modbusAddress("T2")), 42);
    EXPECT_EQ(answerRequest(memory, Bytes{3, 0x01, 0x2C, 0, 2}), (Bytes{3, 4, 0, 0x02, 0, 0x01}));
    EXPECT_EQ(answerRequest(memory, Bytes{3, 0x2E, 0xE1, 0, 1}),
              (Bytes{3, 2, 0, 42}));                                                // 12001 = T2
    EXPECT_EQ(answerRequest(memory, Bytes{2, 0x12, 0xC1, 0, 1}), (Bytes{2, 1, 1})); // 4801 = T2
}

TEST(Pl110Modbus, WritesVariablesBitsAndCoils) {
    Memory memory;
    EXPECT_EQ(answerRequest(memory, Bytes{6, 0x07, 0xDA, 0x12, 0x34}),
              (Bytes{6, 0x07, 0xDA, 0x12, 0x34}));
    EXPECT_EQ(memory.value(modbusAddress("VW10")), 0x1234);
    EXPECT_EQ(answerRequest(memory, Bytes{16, 0x07, 0xD0, 0, 2, 4, 0, 7, 0xFF, 0xFF}),
              (Bytes{16, 0x07, 0xD0, 0, 2}));
    EXPECT_EQ(memory.value(modbusAddress("VD0")), 0x0007FFFF);
    // Bit 32000 + 16 * 3 + 4 is V3.4.
    EXPECT_EQ(answerRequest(memory, Bytes{5, 0x7D, 0x34, 0xFF, 0}),
              (Bytes{5, 0x7D, 0x34, 0xFF, 0}));
    EXPECT_TRUE(memory.bit(modbusAddress("V3.4")));
    EXPECT_EQ(answerRequest(memory, Bytes{15, 0x06, 0x40, 0, 3, 1, 0x05}),
              (Bytes{15, 0x06, 0x40, 0, 3}));
    EXPECT_TRUE(memory.bit(modbusAddress("I1")));
    EXPECT_FALSE(memory.bit(modbusAddress("I2")));
    EXPECT_TRUE(memory.bit(modbusAddress("I3")));
}

TEST(Pl110Modbus, RefusesWhatTheMapDoesNotAllowAndChangesNothing) {
    Memory memory;
    EXPECT_EQ(answerRequest(memory, Bytes{3, 0, 6, 0, 1}), (Bytes{0x83, 2}));        // a hole
    EXPECT_EQ(answerRequest(memory, Bytes{3, 0x07, 0xD0, 0, 31}), (Bytes{0x83, 3})); // 31 words
    EXPECT_EQ(answerRequest(memory, Bytes{6, 0, 100, 0, 1}), (Bytes{0x86, 2}));      // input word
    EXPECT_EQ(answerRequest(memory, Bytes{6, 0x4A, 0x38, 0, 1}), (Bytes{0x86, 2}));  // AI1, 19000
    EXPECT_EQ(answerRequest(memory, Bytes{6, 0x03, 0xEE, 0, 1}),
              (Bytes{0x86, 2})); // SMW6, scan time
    EXPECT_EQ(answerRequest(memory, Bytes{5, 0x12, 0xC0, 0xFF, 0}), (Bytes{0x85, 2})); // T1 contact
    EXPECT_EQ(answerRequest(memory, Bytes{5, 0x09, 0x60, 0x12, 0}),
              (Bytes{0x85, 3})); // not FF00/0000
    EXPECT_EQ(answerRequest(memory, Bytes{16, 0x07, 0xDD, 0, 2, 4, 0, 1, 0, 2}),
              (Bytes{16, 0x07, 0xDD, 0, 2}));
    // 2348 and 2349 are VW348 and VW349; 2350 is past the end: nothing is written.
    EXPECT_EQ(answerRequest(memory, Bytes{16, 0x09, 0x2D, 0, 2, 4, 0, 9, 0, 9}), (Bytes{0x90, 2}));
    EXPECT_EQ(memory.value(modbusAddress("VW349")), 0);
    EXPECT_EQ(answerRequest(memory, Bytes{8, 0, 0}), (Bytes{0x88, 1}));
    EXPECT_EQ(answerRequest(memory, Bytes{3, 0}), (Bytes{0x83, 3}));
}

} // namespace
} // namespace rs::pl110
