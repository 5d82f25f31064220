// SPDX-License-Identifier: GPL-3.0-or-later
#include "Address.h"

#include <array>

namespace rs::lang {

namespace {

struct PrefixEntry {
    std::string_view upper;
    AddressKind kind;
};

// Longest prefixes first is not needed: the whole letter run is compared.
constexpr std::array<PrefixEntry, 13> kPrefixes{{
    {"I", AddressKind::Input},
    {"Q", AddressKind::Output},
    {"IQ", AddressKind::InputOutput},
    {"IA", AddressKind::AnalogInput},
    {"M", AddressKind::Memory},
    {"GM", AddressKind::GlobalMemory},
    {"SM", AddressKind::SystemMemory},
    {"R", AddressKind::Register},
    {"DR", AddressKind::DoubleRegister},
    {"SR", AddressKind::SystemRegister},
    {"ASI", AddressKind::AsiInput},
    {"ASQ", AddressKind::AsiOutput},
    {"S", AddressKind::Sequence},
}};

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
bool isAsciiLetter(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}
// Addresses are ASCII: other letters are never part of a prefix.
char upper(char c) {
    return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
}

// Reads a run of digits at pos; returns false when there is none or it is too long.
bool readNumber(std::string_view word, size_t& pos, int& value, bool& tooLong) {
    size_t start = pos;
    long long v = 0;
    while (pos < word.size() && isDigit(word[pos])) {
        if (v < 100000000)
            v = v * 10 + (word[pos] - '0');
        ++pos;
    }
    if (pos == start)
        return false;
    if (v > 65535) {
        tooLong = true;
        v = 65535;
    }
    value = static_cast<int>(v);
    return true;
}

bool equalsUpper(std::string_view text, std::string_view upperText) {
    if (text.size() != upperText.size())
        return false;
    for (size_t i = 0; i < text.size(); ++i)
        if (upper(text[i]) != upperText[i])
            return false;
    return true;
}

} // namespace

bool Address::isBit() const {
    switch (kind) {
    case AddressKind::Input:
    case AddressKind::Output:
    case AddressKind::InputOutput:
    case AddressKind::AnalogInput:
    case AddressKind::Memory:
    case AddressKind::GlobalMemory:
    case AddressKind::SystemMemory:
    case AddressKind::RegisterBit:
    case AddressKind::AsiInput:
    case AddressKind::AsiOutput:
        return true;
    default:
        return false;
    }
}

bool Address::isWord() const {
    switch (kind) {
    case AddressKind::AnalogInput:
    case AddressKind::Register:
    case AddressKind::DoubleRegister:
    case AddressKind::DoubleRegisterLow:
    case AddressKind::DoubleRegisterHigh:
    case AddressKind::SystemRegister:
        return true;
    default:
        return false;
    }
}

AddressWord readAddressWord(std::string_view word) {
    AddressWord result;
    size_t pos = 0;
    while (pos < word.size() && isAsciiLetter(word[pos]))
        ++pos;
    std::string_view letters = word.substr(0, pos);
    // Letters and digits with no dot ("M10", "Stop2") are names, not
    // addresses; the prefixes have at most three letters.
    if (letters.empty() || letters.size() > 3 || pos >= word.size() || !isDigit(word[pos]) ||
        word.find('.', pos) == std::string_view::npos)
        return result;
    const PrefixEntry* prefix = nullptr;
    for (const auto& entry : kPrefixes)
        if (equalsUpper(letters, entry.upper)) {
            prefix = &entry;
            break;
        }
    if (!prefix)
        return result;

    auto malformed = [&](std::string message) {
        result.shape = AddressWord::Shape::Malformed;
        result.error = std::move(message);
        return result;
    };
    const auto shown = [word] {
        return std::string(word);
    }; // for messages only
    bool tooLong = false;
    Address address;
    address.kind = prefix->kind;
    readNumber(word, pos, address.unit, tooLong);
    if (pos >= word.size() || word[pos] != '.')
        return malformed("malformed address '" + shown() + "': expected '.' after the unit number");
    ++pos;
    if (!readNumber(word, pos, address.index, tooLong))
        return malformed("malformed address '" + shown() + "': expected a number after '.'");
    if (tooLong)
        return malformed("number too large in address '" + shown() + "'");

    auto finish = [&]() {
        if (pos != word.size())
            return malformed("malformed address '" + shown() + "'");
        result.shape = AddressWord::Shape::Variable;
        result.address = address;
        return result;
    };

    switch (prefix->kind) {
    case AddressKind::Sequence:
        if (pos < word.size() && word[pos] == '_') {
            ++pos;
            StepAddress step{address.unit, address.index, 0};
            if (!readNumber(word, pos, step.step, tooLong) || tooLong || pos != word.size())
                return malformed("malformed step header '" + shown() +
                                 "': expected S<unit>.<sequence>_<step>");
            result.shape = AddressWord::Shape::Step;
            result.step = step;
            return result;
        }
        return finish();
    case AddressKind::Register:
        if (pos < word.size() && word[pos] == '.') {
            ++pos;
            if (!readNumber(word, pos, address.bit, tooLong) || tooLong)
                return malformed("malformed register bit '" + shown() +
                                 "': expected R<unit>.<register>.<bit>");
            address.kind = AddressKind::RegisterBit;
        }
        return finish();
    case AddressKind::DoubleRegister:
        if (pos < word.size() && word[pos] == '.') {
            std::string_view half = word.substr(pos + 1);
            if (equalsUpper(half, "LO"))
                address.kind = AddressKind::DoubleRegisterLow;
            else if (equalsUpper(half, "HI"))
                address.kind = AddressKind::DoubleRegisterHigh;
            else
                return malformed("malformed double register '" + shown() +
                                 "': only .Lo or .Hi may follow");
            pos = word.size();
        }
        return finish();
    case AddressKind::AsiInput:
    case AddressKind::AsiOutput:
        if (pos < word.size() && upper(word[pos]) == 'B') {
            address.asiB = true;
            ++pos;
        }
        if (pos < word.size() && word[pos] == '.') {
            ++pos;
            if (!readNumber(word, pos, address.bit, tooLong) || tooLong)
                return malformed("malformed AS-i address '" + shown() + "': expected a bit number");
        }
        if ((address.asiB || prefix->kind == AddressKind::AsiOutput) && address.bit < 0)
            return malformed("malformed AS-i address '" + shown() +
                             "': expected a bit number, as in " +
                             std::string(addressPrefix(prefix->kind)) + "0.1.1");
        return finish();
    default:
        return finish();
    }
}

std::string_view addressPrefix(AddressKind kind) {
    switch (kind) {
    case AddressKind::None:
        return "";
    case AddressKind::Input:
        return "I";
    case AddressKind::Output:
        return "Q";
    case AddressKind::InputOutput:
        return "IQ";
    case AddressKind::AnalogInput:
        return "IA";
    case AddressKind::Memory:
        return "M";
    case AddressKind::GlobalMemory:
        return "GM";
    case AddressKind::SystemMemory:
        return "SM";
    case AddressKind::Register:
    case AddressKind::RegisterBit:
        return "R";
    case AddressKind::DoubleRegister:
    case AddressKind::DoubleRegisterLow:
    case AddressKind::DoubleRegisterHigh:
        return "DR";
    case AddressKind::SystemRegister:
        return "SR";
    case AddressKind::AsiInput:
        return "ASi";
    case AddressKind::AsiOutput:
        return "ASq";
    case AddressKind::Sequence:
        return "S";
    }
    return "";
}

std::string toString(const Address& address) {
    std::string text(addressPrefix(address.kind));
    text += std::to_string(address.unit);
    text += '.';
    text += std::to_string(address.index);
    switch (address.kind) {
    case AddressKind::RegisterBit:
        text += '.' + std::to_string(address.bit);
        break;
    case AddressKind::DoubleRegisterLow:
        text += ".Lo";
        break;
    case AddressKind::DoubleRegisterHigh:
        text += ".Hi";
        break;
    case AddressKind::AsiInput:
    case AddressKind::AsiOutput:
        if (address.asiB)
            text += 'B';
        if (address.bit >= 0)
            text += '.' + std::to_string(address.bit);
        break;
    default:
        break;
    }
    return text;
}

std::string toString(const StepAddress& step) {
    return "S" + std::to_string(step.unit) + '.' + std::to_string(step.sequence) + '_' +
           std::to_string(step.step);
}

} // namespace rs::lang
