// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

// The PL110's memory areas (datasheet section 2.1, Modbus map section 3) as
// one table: what the address reader, the checks, the engine's memory, the
// Modbus slave and the variables page all read (docs/pl110.md).
namespace rs::pl110 {

enum class Area : std::uint8_t {
    Input,         // I1..I256, bits of 16 words
    Output,        // Q1..Q256
    Marker,        // M1..M128
    Bistable,      // B1..B32
    Timer,         // T1..T48: contact and value
    Counter,       // C1..C16: contact and value
    Variable,      // VW0..VW349, bits V0.0.., doubles VD0..
    SpecialMarker, // SMW0..SMW185, bits SM0.0.., doubles SMD0..
    AnalogInput,   // AI1..AI4
    AnalogOutput,  // AQ1
    TimerPreset,   // PT1..PT48
    CounterPreset, // PV1..PV16
    Eeprom,        // EEP0..EEP999
};

inline constexpr int kAreaCount = 13;

// How an area is named and numbered and what may touch it.
struct AreaInfo {
    Area area;
    std::string_view bitPrefix;    // contact or coil spelling ("I"), empty when no bit access
    std::string_view wordPrefix;   // word spelling ("VW", "AI"), empty when no word access
    std::string_view doublePrefix; // "VD", "SMD", empty when none
    int first;                     // first number
    int last;                      // last number (of the word or of the bit)
    bool bitsOfWords;              // bits written word.bit (V3.4, SM0.1) rather than numbered
    bool programWrites;            // a coil, SBIT/RBIT or an assignment may write it
    bool modbusWrites;             // a Modbus master may write it
    int modbusWord;                // Modbus address of the first word, -1 when not mapped
    int modbusBit;                 // Modbus address of the first bit, -1 when not mapped
    int modbusContactWord;         // T and C: their contacts packed 16 to a word; -1 for the rest
    std::string_view description;  // in English; the IDE translates it
};

std::span<const AreaInfo> areaTable();
const AreaInfo& areaInfo(Area area);

// Words an area occupies in memory: bit areas are packed 16 to a word.
int wordCount(Area area);

} // namespace rs::pl110
