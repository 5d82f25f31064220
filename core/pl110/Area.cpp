// SPDX-License-Identifier: GPL-3.0-or-later
#include "Area.h"

#include <QtGlobal>

#include <array>

namespace rs::pl110 {

namespace {

// Sizes, numbering and Modbus addresses from the datasheet (docs/pl110.md
// lists the line of each and the choices where it contradicts itself). The
// descriptions are translated where they are shown.
constexpr std::array<AreaInfo, kAreaCount> kAreas{{
    {Area::Input, "I", "", "", 1, 256, false, false, true, 100, 1600, -1,
     QT_TRANSLATE_NOOP("rs::pl110::Area",
                       "Digital inputs: I1-I8 on the terminals, the rest from expansion modules")},
    {Area::Output, "Q", "", "", 1, 256, false, true, true, 150, 2400, -1,
     QT_TRANSLATE_NOOP("rs::pl110::Area",
                       "Digital outputs: Q1-Q8 are the relays, the rest go to expansion modules")},
    {Area::Marker, "M", "", "", 1, 128, false, true, true, 250, 4000, -1,
     QT_TRANSLATE_NOOP("rs::pl110::Area", "Markers")},
    {Area::Bistable, "B", "", "", 1, 32, false, true, true, 200, 3200, -1,
     QT_TRANSLATE_NOOP("rs::pl110::Area",
                       "Bistable relays: each energisation of the coil changes the contact")},
    {Area::Timer, "T", "T", "", 1, 48, false, true, true, 12000, 4800, 300,
     QT_TRANSLATE_NOOP("rs::pl110::Area",
                       "Timers: the contact and the value in units of the time base")},
    {Area::Counter, "C", "C", "", 1, 16, false, true, true, 14000, 5600, 350,
     QT_TRANSLATE_NOOP("rs::pl110::Area", "Counters: the contact and the value")},
    {Area::Variable, "V", "VW", "VD", 0, 349, true, true, true, 2000, 32000, -1,
     QT_TRANSLATE_NOOP("rs::pl110::Area", "Variables, kept by the battery")},
    {Area::SpecialMarker, "SM", "SMW", "SMD", 0, 185, true, true, true, 1000, 16000, -1,
     QT_TRANSLATE_NOOP("rs::pl110::Area",
                       "Special markers: status, clocks, scan times and settings")},
    {Area::AnalogInput, "", "AI", "", 1, 4, false, false, false, 19000, -1, -1,
     QT_TRANSLATE_NOOP("rs::pl110::Area", "Analogue inputs, scaled by RANGE")},
    {Area::AnalogOutput, "", "AQ", "", 1, 1, false, true, true, 19400, -1, -1,
     QT_TRANSLATE_NOOP("rs::pl110::Area", "Analogue output, 0-10 V")},
    {Area::TimerPreset, "", "PT", "", 1, 48, false, true, true, 13000, -1, -1,
     QT_TRANSLATE_NOOP("rs::pl110::Area", "Timer presets")},
    {Area::CounterPreset, "", "PV", "", 1, 16, false, true, true, 15000, -1, -1,
     QT_TRANSLATE_NOOP("rs::pl110::Area", "Counter presets")},
    {Area::Eeprom, "", "EEP", "", 0, 999, false, true, true, 20000, -1, -1,
     QT_TRANSLATE_NOOP("rs::pl110::Area", "EEPROM words, kept without power")},
}};

} // namespace

std::span<const AreaInfo> areaTable() {
    return kAreas;
}

const AreaInfo& areaInfo(Area area) {
    return kAreas[static_cast<std::size_t>(area)];
}

int wordCount(Area area) {
    const AreaInfo& info = areaInfo(area);
    const int numbers = info.last - info.first + 1;
    const bool packedBits = !info.bitPrefix.empty() && !info.bitsOfWords && info.wordPrefix.empty();
    return packedBits ? (numbers + 15) / 16 : numbers;
}

} // namespace rs::pl110
