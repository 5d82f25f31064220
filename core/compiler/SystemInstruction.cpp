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

const SystemParameter* findParameter(const SystemInstruction& instruction, std::string_view name) {
    for (const auto& parameter : instruction.parameters)
        if (sameName(parameter.name, name))
            return &parameter;
    return nullptr;
}

std::string systemInstructionNames() {
    std::string names;
    for (const auto& instruction : kSystemInstructions)
        names += (names.empty() ? "" : ", ") + std::string(instruction.name);
    return names;
}

} // namespace rs::compiler
