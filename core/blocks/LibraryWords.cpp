// SPDX-License-Identifier: GPL-3.0-or-later
#include "LibraryWords.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <string>
#include <utility>

namespace rs::blocks {

namespace {

template <typename Enum, std::size_t N>
using WordTable = std::array<std::pair<Enum, std::string_view>, N>;

constexpr WordTable<BlockKind, 2> kBlockKinds{
    {{BlockKind::Macro, "macro"}, {BlockKind::System, "system"}}};
constexpr WordTable<PinDirection, 2> kDirections{
    {{PinDirection::In, "in"}, {PinDirection::Out, "out"}}};
constexpr WordTable<PinKind, 5> kPinKinds{{{PinKind::Bit, "bit"},
                                           {PinKind::Register, "register"},
                                           {PinKind::DoubleRegister, "double-register"},
                                           {PinKind::Time, "time"},
                                           {PinKind::Constant, "constant"}}};
constexpr WordTable<PinRole, 2> kRoles{
    {{PinRole::Primary, "primary"}, {PinRole::Secondary, "secondary"}}};
constexpr WordTable<OperandKind, 11> kOperands{{{OperandKind::Input, "input"},
                                                {OperandKind::Output, "output"},
                                                {OperandKind::Memory, "memory"},
                                                {OperandKind::GlobalMemory, "global-memory"},
                                                {OperandKind::SystemMemory, "system-memory"},
                                                {OperandKind::RegisterBit, "register-bit"},
                                                {OperandKind::Register, "register"},
                                                {OperandKind::DoubleRegister, "double-register"},
                                                {OperandKind::SystemRegister, "system-register"},
                                                {OperandKind::TimeConstant, "time-constant"},
                                                {OperandKind::Number, "number"}}};
constexpr WordTable<PrivateKind, 3> kPrivateKinds{
    {{PrivateKind::Memory, "memory"},
     {PrivateKind::Register, "register"},
     {PrivateKind::DoubleRegister, "double-register"}}};

template <typename Enum, std::size_t N>
std::string_view word(const WordTable<Enum, N>& table, Enum value) {
    for (const auto& [entry, text] : table)
        if (entry == value)
            return text;
    return {};
}

template <typename Enum, std::size_t N>
std::optional<Enum> value(const WordTable<Enum, N>& table, std::string_view text) {
    for (const auto& [entry, spelling] : table)
        if (spelling == text)
            return entry;
    return std::nullopt;
}

} // namespace

std::string_view wordOf(BlockKind kind) {
    return word(kBlockKinds, kind);
}
std::string_view wordOf(PinDirection direction) {
    return word(kDirections, direction);
}
std::string_view wordOf(PinKind kind) {
    return word(kPinKinds, kind);
}
std::string_view wordOf(PinRole role) {
    return word(kRoles, role);
}
std::string_view wordOf(OperandKind kind) {
    return word(kOperands, kind);
}
std::string_view wordOf(PrivateKind kind) {
    return word(kPrivateKinds, kind);
}

std::optional<BlockKind> blockKindOf(std::string_view text) {
    return value(kBlockKinds, text);
}
std::optional<PinDirection> pinDirectionOf(std::string_view text) {
    return value(kDirections, text);
}
std::optional<PinKind> pinKindOf(std::string_view text) {
    return value(kPinKinds, text);
}
std::optional<PinRole> pinRoleOf(std::string_view text) {
    return value(kRoles, text);
}
std::optional<OperandKind> operandKindOf(std::string_view text) {
    return value(kOperands, text);
}
std::optional<PrivateKind> privateKindOf(std::string_view text) {
    return value(kPrivateKinds, text);
}

std::vector<OperandKind> possibleOperands(PinKind kind, PinDirection direction) {
    using enum OperandKind;
    const bool in = direction == PinDirection::In;
    switch (kind) {
    case PinKind::Bit:
        if (in)
            return {Input, Output, Memory, GlobalMemory, SystemMemory, RegisterBit};
        return {Output, Memory, GlobalMemory, SystemMemory, RegisterBit};
    case PinKind::Register:
        if (in)
            return {Register, SystemRegister, Number};
        return {Register, SystemRegister};
    case PinKind::DoubleRegister:
        if (in)
            return {DoubleRegister, Number};
        return {DoubleRegister};
    case PinKind::Time:
        if (in)
            return {Register, TimeConstant};
        return {Register};
    case PinKind::Constant:
        if (in)
            return {Number};
        return {};
    }
    return {};
}

std::optional<std::int64_t> canonicalInteger(std::string_view text) {
    std::int64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
        return std::nullopt;
    if (std::to_string(value) != text)
        return std::nullopt;
    return value;
}

bool isTimeConstant(std::string_view text) {
    const std::size_t s = text.find('s');
    if (s == std::string_view::npos || text.size() != s + 3)
        return false;
    const auto seconds = canonicalInteger(text.substr(0, s));
    const std::string_view hundredths = text.substr(s + 1);
    if (!seconds || *seconds < 0 || hundredths[0] < '0' || hundredths[0] > '9' ||
        hundredths[1] < '0' || hundredths[1] > '9')
        return false;
    return *seconds * 100 + (hundredths[0] - '0') * 10 + (hundredths[1] - '0') <= 65535;
}

std::optional<int> stateCodeOf(std::string_view word) {
    if (word.size() != 7 || word.substr(0, 3) != "16#")
        return std::nullopt;
    int code = 0;
    for (const char c : word.substr(3)) {
        const int digit = c >= '0' && c <= '9'   ? c - '0'
                          : c >= 'A' && c <= 'F' ? c - 'A' + 10
                          : c >= 'a' && c <= 'f' ? c - 'a' + 10
                                                 : -1;
        if (digit < 0)
            return std::nullopt;
        code = code * 16 + digit;
    }
    return code;
}

std::string stateCodeWord(int code) {
    static constexpr char kDigits[] = "0123456789ABCDEF";
    std::string word = "16#";
    for (int shift = 12; shift >= 0; shift -= 4)
        word += kDigits[(code >> shift) & 0xF];
    return word;
}

bool isLibraryName(std::string_view name) {
    const auto letter = [](char c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
    };
    if (name.empty() || !letter(name.front()))
        return false;
    return std::all_of(name.begin(), name.end(),
                       [&](char c) { return letter(c) || (c >= '0' && c <= '9') || c == '_'; });
}

} // namespace rs::blocks
