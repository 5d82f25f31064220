// SPDX-License-Identifier: GPL-3.0-or-later
#include "SystemInstruction.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace rs::compiler {

namespace {

bool sameName(std::string_view a, std::string_view b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](char x, char y) {
        return std::tolower(static_cast<unsigned char>(x)) ==
               std::tolower(static_cast<unsigned char>(y));
    });
}

// Ids are the rows' numbers from 1, so that an id indexes the table.
constexpr bool idsAreRowNumbers() {
    for (std::size_t row = 0; row < std::size(kSystemInstructions); ++row)
        if (static_cast<std::size_t>(kSystemInstructions[row].id) != row + 1)
            return false;
    return true;
}
static_assert(idsAreRowNumbers());

} // namespace

const SystemInstruction* findSystemInstruction(std::string_view name) {
    for (const auto& instruction : kSystemInstructions)
        if (sameName(instruction.name, name))
            return &instruction;
    return nullptr;
}

const SystemInstruction* findSystemInstruction(std::uint8_t id) {
    if (id < 1 || id > std::size(kSystemInstructions))
        return nullptr;
    return &kSystemInstructions[id - 1];
}

int standardIoType(SystemInstructionId id) {
    using enum SystemInstructionId;
    switch (id) {
    case ToGatewayErrorCode:
        return 100;
    case ToGatewayB46:
        return 101;
    case ToGatewayAsi16To31Safe:
        return 102;
    case ToGatewayAsi1To3NonSafe:
    case ToGatewayAsi4To7NonSafe:
    case ToGatewayAsi8To11NonSafe:
    case ToGatewayAsi12To15NonSafe:
    case ToGatewayAsi16To19NonSafe:
    case ToGatewayAsi20To23NonSafe:
    case ToGatewayAsi24To27NonSafe:
    case ToGatewayAsi28To31NonSafe: // 103-110 in the order of the ids
        return 103 + static_cast<int>(id) - static_cast<int>(ToGatewayAsi1To3NonSafe);
    case ToGatewayB42Asi:
        return 112;
    case ToGatewayAsi1To15Safe:
        return 113;
    default:
        return 0;
    }
}

bool isToGateway(SystemInstructionId id) {
    return id >= SystemInstructionId::ToGatewayUserA &&
           id <= SystemInstructionId::ToGatewayAsi1To15Safe;
}

const SystemParameter* findParameter(const SystemInstruction& instruction, std::string_view name) {
    for (const auto& parameter : instruction.parameters)
        if (sameName(parameter.name, name))
            return &parameter;
    return nullptr;
}

std::string systemInstructionHint(std::string_view unknown) {
    const auto lower = [](std::string_view text) {
        std::string folded(text.substr(0, 3));
        for (char& c : folded)
            c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return folded;
    };
    std::string names;
    for (const auto& instruction : kSystemInstructions)
        if (unknown.size() >= 3 && lower(instruction.name) == lower(unknown))
            names += (names.empty() ? "" : ", ") + std::string(instruction.name);
    if (!names.empty())
        return "did you mean " + names + "?";
    return "Rungsmith's image has " + std::to_string(std::size(kSystemInstructions)) +
           ", listed in docs/image-format.md, \"System instructions\"";
}

} // namespace rs::compiler
