// SPDX-License-Identifier: GPL-3.0-or-later
#include "ExportedVariables.h"

#include "UnitSettings.h"

#include <set>

namespace rs::project {

namespace {

using lang::AddressKind;

constexpr int kBitsPerTelegramPair = 32;
constexpr int kBitsPerRegister = 16;

// Pairs for a set of exported variables: double registers fill a pair each;
// registers take half a pair and Booleans fill whatever room is left.
int pairsFor(int booleans, int registers, int doubleRegisters) {
    const int bits = booleans + registers * kBitsPerRegister;
    return doubleRegisters + (bits + kBitsPerTelegramPair - 1) / kBitsPerTelegramPair;
}

int pairsWith(const std::set<lang::Address>& exported, int station, const lang::Address* added) {
    int booleans = 0;
    int registers = 0;
    int doubleRegisters = 0;
    auto count = [&](const lang::Address& address) {
        if (address.unit != station)
            return;
        if (address.kind == AddressKind::Register)
            ++registers;
        else if (address.kind == AddressKind::DoubleRegister)
            ++doubleRegisters;
        else
            ++booleans;
    };
    for (const auto& address : exported)
        count(address);
    if (added)
        count(*added);
    return pairsFor(booleans, registers, doubleRegisters);
}

} // namespace

std::optional<std::string> checkExportable(const Project& project, const lang::Address& address) {
    const auto settings = unitSettings(project, address.unit);
    if (!settings)
        return "the project has no unit " + std::to_string(address.unit);
    const target::UnitTypeInfo& type = target::unitTypeInfo(settings->type);
    const std::string name = lang::toString(address);
    if (settings->instructionSet < 3)
        return name + " cannot be exported: export variables need instruction set 3";
    const bool listed =
        address.kind == AddressKind::Register || address.kind == AddressKind::DoubleRegister ||
        address.kind == AddressKind::Memory || address.kind == AddressKind::Output ||
        address.kind == AddressKind::Input || address.kind == AddressKind::AnalogInput ||
        (address.kind == AddressKind::AsiInput && address.bit < 0); // a safe AS-i input
    if (!listed)
        return name + " cannot be exported; registers, double registers, memories, outputs and "
                      "safety inputs can";
    if (!target::hasVariable(type, address, settings->instructionSet))
        return "a " + std::string(type.display) + " has no " + name;
    if (target::isGlobal(type, address))
        return name + " is global: the other units see it already";
    return std::nullopt;
}

int telegramPairs(const Project& project, int station) {
    return pairsWith(project.exportedVariables, station, nullptr);
}

int telegramPairs(const std::set<lang::Address>& exported, int station) {
    return pairsWith(exported, station, nullptr);
}

int telegramPairs(const Project& project) {
    std::set<int> stations;
    for (const auto& address : project.exportedVariables)
        stations.insert(address.unit);
    int total = 0;
    for (int station : stations)
        total += telegramPairs(project, station);
    return total;
}

std::optional<std::string> setExported(Project& project, const lang::Address& address,
                                       bool exported) {
    if (!exported) {
        project.exportedVariables.erase(address);
        return std::nullopt;
    }
    if (project.exportedVariables.count(address))
        return std::nullopt;
    if (auto problem = checkExportable(project, address))
        return problem;
    const int unitPairs = pairsWith(project.exportedVariables, address.unit, &address);
    if (unitPairs > kTelegramPairsPerUnit)
        return "exporting " + lang::toString(address) + " would need " + std::to_string(unitPairs) +
               " extra telegram pairs; a unit may add " + std::to_string(kTelegramPairsPerUnit);
    const int projectPairs =
        telegramPairs(project) - telegramPairs(project, address.unit) + unitPairs;
    if (projectPairs > kTelegramPairsPerProject)
        return "exporting " + lang::toString(address) + " would need " +
               std::to_string(projectPairs) + " extra telegram pairs in the project; at most " +
               std::to_string(kTelegramPairsPerProject) + " are allowed";
    project.exportedVariables.insert(address);
    return std::nullopt;
}

} // namespace rs::project
