// SPDX-License-Identifier: GPL-3.0-or-later
#include "Address.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace rs::pl110 {

namespace {

struct Spelling {
    std::string_view prefix;
    Area area;
    Width width;
};

// Longest prefixes first, so "SMW3" is not read as "SM" + "W3".
constexpr std::array<Spelling, 17> kSpellings{{
    {"SMW", Area::SpecialMarker, Width::Word},
    {"SMD", Area::SpecialMarker, Width::Double},
    {"EEP", Area::Eeprom, Width::Word},
    {"SM", Area::SpecialMarker, Width::Bit},
    {"VW", Area::Variable, Width::Word},
    {"VD", Area::Variable, Width::Double},
    {"AI", Area::AnalogInput, Width::Word},
    {"AQ", Area::AnalogOutput, Width::Word},
    {"PT", Area::TimerPreset, Width::Word},
    {"PV", Area::CounterPreset, Width::Word},
    {"V", Area::Variable, Width::Bit},
    {"I", Area::Input, Width::Bit},
    {"Q", Area::Output, Width::Bit},
    {"M", Area::Marker, Width::Bit},
    {"B", Area::Bistable, Width::Bit},
    {"T", Area::Timer, Width::Bit},
    {"C", Area::Counter, Width::Bit},
}};

bool startsWithIgnoringCase(std::string_view word, std::string_view prefix) {
    if (word.size() < prefix.size())
        return false;
    for (std::size_t i = 0; i < prefix.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(word[i])) != prefix[i])
            return false;
    return true;
}

bool allDigits(std::string_view text) {
    return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c));
    });
}

// Numbers longer than this are out of every range; reading stops before overflow.
int number(std::string_view digits) {
    int value = 0;
    for (char c : digits) {
        value = value * 10 + (c - '0');
        if (value > 99999)
            return 99999;
    }
    return value;
}

std::string rangeText(const AreaInfo& info, std::string_view prefix, int last) {
    return std::string(prefix) + std::to_string(info.first) + "-" + std::string(prefix) +
           std::to_string(last);
}

} // namespace

AddressReading readAddress(std::string_view word) {
    AddressReading reading;
    for (const Spelling& spelling : kSpellings) {
        if (!startsWithIgnoringCase(word, spelling.prefix))
            continue;
        const std::string_view rest = word.substr(spelling.prefix.size());
        const std::size_t dot = rest.find('.');
        const std::string_view whole = rest.substr(0, dot);
        const std::string_view bitText =
            dot == std::string_view::npos ? std::string_view{} : rest.substr(dot + 1);
        if (!allDigits(whole) || (dot != std::string_view::npos && !allDigits(bitText)))
            return reading; // a name such as "Motor" or "Tank.Level"
        const AreaInfo& info = areaInfo(spelling.area);
        Address address{spelling.area, spelling.width, number(whole), -1};
        const std::string upper(spelling.prefix);
        reading.shape = AddressReading::Shape::Malformed;
        if (info.bitsOfWords && spelling.width == Width::Bit) {
            if (dot == std::string_view::npos) {
                reading.error = upper + std::string(whole) + " needs a bit: " + upper +
                                std::string(whole) + ".0-" + upper + std::string(whole) +
                                ".15, or the word " + std::string(info.wordPrefix) +
                                std::string(whole);
                return reading;
            }
            address.bit = number(bitText);
            if (address.bit > 15) {
                reading.error = "bit " + std::string(bitText) + " of " + upper +
                                std::string(whole) + " is out of range: bits are 0-15";
                return reading;
            }
        } else if (dot != std::string_view::npos) {
            reading.error = upper + " has no bit access: write " + upper + std::string(whole);
            return reading;
        }
        // A double word spans two words: the last one starts one before the end.
        const int last = info.last - (spelling.width == Width::Double ? 1 : 0);
        if (address.number < info.first || address.number > last) {
            reading.error =
                toString(address) + " is out of range: " + rangeText(info, spelling.prefix, last);
            return reading;
        }
        reading.shape = AddressReading::Shape::Address;
        reading.address = address;
        return reading;
    }
    return reading;
}

Address asWord(Address address) {
    if ((address.area == Area::Timer || address.area == Area::Counter) &&
        address.width == Width::Bit)
        address.width = Width::Word;
    return address;
}

std::string toString(const Address& address) {
    const AreaInfo& info = areaInfo(address.area);
    std::string_view prefix = info.bitPrefix;
    if (address.width == Width::Word)
        prefix = info.wordPrefix;
    else if (address.width == Width::Double)
        prefix = info.doublePrefix;
    std::string text = std::string(prefix) + std::to_string(address.number);
    if (address.bit >= 0)
        text += "." + std::to_string(address.bit);
    return text;
}

MemoryPlace memoryPlace(const Address& address) {
    const AreaInfo& info = areaInfo(address.area);
    const int offset = address.number - info.first;
    if (address.bit >= 0)
        return {offset, address.bit};
    if (address.width == Width::Bit && info.wordPrefix.empty())
        return {offset / 16, offset % 16};
    return {offset, -1};
}

} // namespace rs::pl110
