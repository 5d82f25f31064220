// SPDX-License-Identifier: GPL-3.0-or-later
#include "RemanentVariables.h"

#include "UnitSettings.h"

#include <algorithm>

namespace rs::project {

namespace {

using lang::AddressKind;

bool inRange(int index) {
    return index >= kFirstRemanent && index <= kLastRemanent;
}

char letterOf(AddressKind kind) {
    return kind == AddressKind::Register ? 'R' : 'M';
}

} // namespace

bool canBeRemanent(const target::UnitTypeInfo& type, const lang::Address& address) {
    return type.remanent &&
           (address.kind == AddressKind::Register || address.kind == AddressKind::Memory) &&
           address.bit < 0 && inRange(address.index);
}

std::optional<std::string> checkRemanentSelection(const std::set<lang::Address>& selection) {
    const auto registers = std::count_if(selection.begin(), selection.end(), [](const auto& a) {
        return a.kind == AddressKind::Register;
    });
    const bool anyMemory = std::any_of(selection.begin(), selection.end(),
                                       [](const auto& a) { return a.kind == AddressKind::Memory; });
    if (registers == kLastRemanent - kFirstRemanent + 1 && anyMemory)
        return "when all registers R100-R131 are remanent, no memory can be";
    return std::nullopt;
}

std::set<lang::Address> remanentOf(const Project& project, int station) {
    std::set<lang::Address> result;
    for (const auto& address : project.remanentVariables)
        if (address.unit == station)
            result.insert(address);
    return result;
}

std::optional<std::string> setRemanent(Project& project, int station,
                                       const std::set<lang::Address>& selection) {
    const target::UnitTypeInfo& type = unitTypeOf(project, station);
    if (!selection.empty() && !type.remanent)
        return "a " + std::string(type.display) + " has no remanent variables";
    for (const auto& address : selection)
        if (address.unit != station || !canBeRemanent(type, address))
            return lang::toString(address) + " cannot be remanent; only R" +
                   std::to_string(station) + ".100-131 and M" + std::to_string(station) +
                   ".100-131 can";
    if (auto problem = checkRemanentSelection(selection))
        return problem;
    std::erase_if(project.remanentVariables,
                  [&](const lang::Address& address) { return address.unit == station; });
    project.remanentVariables.insert(selection.begin(), selection.end());
    return std::nullopt;
}

std::string formatRemanentList(const std::set<lang::Address>& variables, int station) {
    std::string text;
    const lang::Address* runStart = nullptr;
    const lang::Address* runEnd = nullptr;
    auto flush = [&] {
        if (!runStart)
            return;
        if (!text.empty())
            text += ',';
        text += letterOf(runStart->kind) + std::to_string(runStart->index);
        if (runEnd->index != runStart->index)
            text += std::string("-") + letterOf(runEnd->kind) + std::to_string(runEnd->index);
    };
    for (const auto& address : variables) {
        if (address.unit != station)
            continue;
        if (runStart && address.kind == runEnd->kind && address.index == runEnd->index + 1) {
            runEnd = &address;
            continue;
        }
        flush();
        runStart = runEnd = &address;
    }
    flush();
    return text;
}

std::set<lang::Address> parseRemanentList(std::string_view text, int station) {
    std::set<lang::Address> result;
    auto fail = [&](std::string_view item) {
        throw RemanentListError{"'" + std::string(item) +
                                "' is not a remanent variable: write R100-R131 or M100-M131, "
                                "runs as R100-R103, separated by commas"};
    };
    auto readOne = [&](std::string_view item) -> lang::Address {
        if (item.size() < 2 ||
            (item[0] != 'R' && item[0] != 'M' && item[0] != 'r' && item[0] != 'm'))
            fail(item);
        const std::string_view digits = item.substr(1);
        if (digits.size() > 3 || digits.find_first_not_of("0123456789") != digits.npos)
            fail(item);
        const int index = std::stoi(std::string(digits));
        if (!inRange(index))
            fail(item);
        const bool isRegister = item[0] == 'R' || item[0] == 'r';
        return {isRegister ? AddressKind::Register : AddressKind::Memory, station, index};
    };
    while (!text.empty()) {
        const auto comma = text.find(',');
        const std::string_view item = text.substr(0, comma);
        text = comma == text.npos ? std::string_view{} : text.substr(comma + 1);
        const auto dash = item.find('-');
        const lang::Address first = readOne(item.substr(0, dash));
        const lang::Address last = dash == item.npos ? first : readOne(item.substr(dash + 1));
        if (last.kind != first.kind || last.index < first.index)
            fail(item);
        for (int index = first.index; index <= last.index; ++index)
            result.insert({first.kind, station, index});
        if (comma != std::string_view::npos && text.empty())
            fail("");
    }
    return result;
}

} // namespace rs::project
