// SPDX-License-Identifier: GPL-3.0-or-later
#include "UnitSettings.h"

#include "BlankLines.h"
#include "ExportedVariables.h"
#include "IoOptions.h"
#include "RemanentVariables.h"
#include "VariableTable.h"

#include <algorithm>
#include <cctype>
#include <set>

namespace rs::project {

namespace {

using lang::Declaration;
using lang::Line;

template <typename T> T* declarationOf(Line& line) {
    if (auto* declaration = std::get_if<Declaration>(&line.body))
        return std::get_if<T>(&declaration->body);
    return nullptr;
}

template <typename T> const T* declarationOf(const Line& line) {
    if (auto* declaration = std::get_if<Declaration>(&line.body))
        return std::get_if<T>(&declaration->body);
    return nullptr;
}

// The lists of lines that may hold id_pluto and type_pluto declarations.
template <typename Document, typename Visit> void forEachDeclarationList(Document& d, Visit visit) {
    visit(d.preamble);
    for (auto& unit : d.units)
        visit(unit.declarations);
}

int stationOf(const Line& line) {
    if (auto* id = declarationOf<lang::IdDeclaration>(line))
        return id->station;
    if (auto* type = declarationOf<lang::TypeDeclaration>(line))
        return type->station;
    return -1;
}

Line blankLine() {
    return {lang::BlankLine{}, std::nullopt, {}};
}

Line declarationLine(lang::DeclarationBody body) {
    return {Declaration{std::move(body), {}}, std::nullopt, {}};
}

lang::IdDeclaration idDeclaration(const UnitSettings& settings) {
    const target::UnitTypeInfo& type = target::unitTypeInfo(settings.type);
    return {type.family, settings.station, settings.idfix};
}

lang::TypeDeclaration typeDeclaration(const UnitSettings& settings) {
    const target::UnitTypeInfo& type = target::unitTypeInfo(settings.type);
    return {settings.station, std::string(type.name), settings.instructionSet};
}

std::optional<std::string> check(const UnitSettings& settings) {
    if (settings.station < 0 || settings.station > 31)
        return "the station number must be 0-31";
    if (auto problem = checkIdfix(settings.idfix))
        return problem;
    if (settings.instructionSet != 2 && settings.instructionSet != 3)
        return "the instruction set is 2 or 3";
    if (settings.instructionSet == 3 && !supportsInstructionSet3(settings.type))
        return "a " + std::string(target::unitTypeInfo(settings.type).display) +
               " runs instruction set 2 only";
    return std::nullopt;
}

// Where a unit's id_pluto and type_pluto lines go: before the first such line
// of a higher station, else after the last one, else after the directives.
std::size_t placeForUnitLines(const std::vector<Line>& preamble, int station) {
    std::size_t afterLast = 0;
    for (std::size_t i = 0; i < preamble.size(); ++i) {
        const int other = stationOf(preamble[i]);
        if (other > station)
            return i;
        if (other >= 0 || std::holds_alternative<lang::Directive>(preamble[i].body))
            afterLast = i + 1;
    }
    return afterLast;
}

// Units follow each other with one blank line between them; the last ends the file.
void separateFromNext(lang::UnitProgram& unit) {
    auto& lines = unit.steps.empty() ? unit.declarations : unit.steps.back().lines;
    if (lines.empty() || !std::holds_alternative<lang::BlankLine>(lines.back().body))
        lines.push_back(blankLine());
}

bool belongsToStation(const lang::Address& address, int station) {
    return address.unit == station;
}

} // namespace

std::vector<UnitSettings> unitsOf(const Project& project) {
    std::vector<UnitSettings> units;
    for (int station : project.stations())
        units.push_back(*unitSettings(project, station));
    return units;
}

std::optional<UnitSettings> unitSettings(const Project& project, int station) {
    const lang::IdDeclaration* id = nullptr;
    const lang::TypeDeclaration* typed = nullptr;
    bool hasCode = false;
    forEachDeclarationList(project.program, [&](const std::vector<Line>& lines) {
        for (const auto& line : lines) {
            if (auto* d = declarationOf<lang::IdDeclaration>(line); d && d->station == station)
                id = id ? id : d;
            if (auto* d = declarationOf<lang::TypeDeclaration>(line); d && d->station == station)
                typed = d; // the last one decides, as for the compiler
        }
    });
    for (const auto& unit : project.program.units)
        hasCode = hasCode || unit.station() == station;
    if (!id && !hasCode)
        return std::nullopt;

    UnitSettings settings;
    settings.station = station;
    settings.declared = id != nullptr;
    const lang::UnitFamily family = id ? id->family : lang::UnitFamily::Pluto;
    settings.type = target::baseType(family);
    if (id)
        settings.idfix = id->idfix;
    if (typed) {
        if (const auto* info = target::findUnitType(typed->type); info && info->family == family)
            settings.type = info->type;
        if (typed->instructionSet)
            settings.instructionSet = typed->instructionSet;
    }
    if (auto it = project.unitDescriptions.find(station); it != project.unitDescriptions.end())
        settings.description = it->second;
    settings.idfixProg = project.idfixProg.count(station) > 0;
    return settings;
}

const target::UnitTypeInfo& unitTypeOf(const Project& project, int station) {
    const auto settings = unitSettings(project, station);
    return target::unitTypeInfo(settings ? settings->type : target::UnitType::A20);
}

int instructionSetOf(const Project& project, int station) {
    const auto settings = unitSettings(project, station);
    return settings ? settings->instructionSet : 2;
}

lang::UnitProgram& programOf(Project& project, int station) {
    auto& units = project.program.units;
    auto at = std::find_if(units.begin(), units.end(),
                           [&](const lang::UnitProgram& u) { return u.station() >= station; });
    if (at != units.end() && at->station() == station)
        return *at;
    lang::UnitProgram unit;
    unit.header = declarationLine(lang::ProgramDeclaration{station});
    unit.declarations.push_back(blankLine());
    unit.steps.push_back({{station, 0, 0}, std::nullopt, {}, {}});
    if (at != units.begin())
        separateFromNext(*(at - 1));
    if (at != units.end())
        separateFromNext(unit);
    at = units.insert(at, std::move(unit));
    return *at;
}

std::vector<int> freeStations(const Project& project) {
    const std::vector<int> used = project.stations();
    std::vector<int> free;
    for (int station = 0; station <= 31; ++station)
        if (std::find(used.begin(), used.end(), station) == used.end())
            free.push_back(station);
    return free;
}

bool supportsInstructionSet3(target::UnitType type) {
    return type != target::UnitType::A16 && type != target::UnitType::B16;
}

std::optional<std::string> checkIdfix(std::string_view idfix) {
    if (idfix.size() != 12 || idfix.find_first_not_of("0123456789abcdefABCDEF") != idfix.npos)
        return "an IDFIX is 12 hexadecimal digits (0-9, A-F)";
    return std::nullopt;
}

std::optional<std::string> addUnit(Project& project, const UnitSettings& requested) {
    if (auto problem = check(requested))
        return problem;
    const std::vector<int> free = freeStations(project);
    if (std::find(free.begin(), free.end(), requested.station) == free.end())
        return "station " + std::to_string(requested.station) + " is already used";
    UnitSettings settings = requested;
    for (char& c : settings.idfix)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));

    auto& preamble = project.program.preamble;
    const std::size_t at = placeForUnitLines(preamble, settings.station);
    std::vector<Line> lines{declarationLine(idDeclaration(settings)),
                            declarationLine(typeDeclaration(settings))};
    // The manuals' layout: "$name", a blank line, the units' declarations, a
    // blank line, then the code.
    if (at > 0 && std::holds_alternative<lang::Directive>(preamble[at - 1].body))
        lines.insert(lines.begin(), blankLine());
    preamble.insert(preamble.begin() + static_cast<std::ptrdiff_t>(at), lines.begin(), lines.end());
    if (!std::holds_alternative<lang::BlankLine>(preamble.back().body))
        preamble.push_back(blankLine());
    if (!settings.description.empty())
        project.unitDescriptions[settings.station] = settings.description;
    if (settings.idfixProg)
        project.idfixProg.insert(settings.station);
    programOf(project, settings.station);
    tidyBlankLines(project.program);
    return std::nullopt;
}

std::optional<std::string> changeUnit(Project& project, const UnitSettings& requested) {
    const auto current = unitSettings(project, requested.station);
    if (!current)
        return "the project has no unit " + std::to_string(requested.station);
    if (auto problem = check(requested))
        return problem;
    UnitSettings settings = requested;
    for (char& c : settings.idfix)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    const int station = settings.station;

    bool hasId = false;
    bool hasType = false;
    forEachDeclarationList(project.program, [&](std::vector<Line>& lines) {
        for (auto& line : lines) {
            if (auto* id = declarationOf<lang::IdDeclaration>(line); id && id->station == station) {
                *id = idDeclaration(settings);
                hasId = true;
            }
            if (auto* type = declarationOf<lang::TypeDeclaration>(line);
                type && type->station == station) {
                *type = typeDeclaration(settings);
                hasType = true;
            }
        }
    });
    auto& preamble = project.program.preamble;
    if (!hasId) {
        const auto at =
            preamble.begin() + static_cast<std::ptrdiff_t>(placeForUnitLines(preamble, station));
        preamble.insert(at, declarationLine(idDeclaration(settings)));
    }
    if (!hasType) {
        auto id = std::find_if(preamble.begin(), preamble.end(), [&](const Line& line) {
            auto* d = declarationOf<lang::IdDeclaration>(line);
            return d && d->station == station;
        });
        if (id != preamble.end())
            preamble.insert(id + 1, declarationLine(typeDeclaration(settings)));
        else
            preamble.insert(preamble.begin() +
                                static_cast<std::ptrdiff_t>(placeForUnitLines(preamble, station)),
                            declarationLine(typeDeclaration(settings)));
    }
    if (settings.description.empty())
        project.unitDescriptions.erase(station);
    else
        project.unitDescriptions[station] = settings.description;
    if (settings.idfixProg)
        project.idfixProg.insert(station);
    else
        project.idfixProg.erase(station);
    if (!target::unitTypeInfo(settings.type).asiSlaves)
        project.asiOptions.erase(station);

    // What the new type or instruction set cannot have goes with the change.
    const target::UnitTypeInfo& type = target::unitTypeInfo(settings.type);
    for (auto& unit : project.program.units) {
        if (unit.station() != station)
            continue;
        std::erase_if(unit.declarations, [&](const Line& line) {
            const auto* io = declarationOf<lang::IoDeclaration>(line);
            if (!io)
                return false;
            const auto terminal = terminalOf(type, *io);
            if (!terminal)
                return true;
            const TerminalSetting setting = settingOf(*terminal, *io);
            return legalSetting(type, *terminal, setting) != setting;
        });
    }
    auto lacks = [&](const lang::Address& address) {
        return !target::hasVariable(type, address, settings.instructionSet) ||
               (settings.instructionSet < 3 && target::instructionSet3Feature(address));
    };
    for (const lang::Address& address : namedAddresses(project, station))
        if (lacks(address))
            setVariableName(project, address, {});
    std::erase_if(project.variableDescriptions, [&](const auto& entry) {
        return belongsToStation(entry.first, station) && lacks(entry.first);
    });
    std::erase_if(project.exportedVariables, [&](const lang::Address& address) {
        return belongsToStation(address, station) && checkExportable(project, address).has_value();
    });
    std::erase_if(project.remanentVariables, [&](const lang::Address& address) {
        return belongsToStation(address, station) && !canBeRemanent(type, address);
    });
    tidyBlankLines(project.program);
    return std::nullopt;
}

namespace {

// Everything of one unit that a change of its type can take away.
int unitItems(const Project& project, int station) {
    int count = 0;
    for (const auto& unit : project.program.units)
        if (unit.station() == station)
            for (const auto& line : unit.declarations)
                count += declarationOf<lang::IoDeclaration>(line) != nullptr;
    count += static_cast<int>(namedAddresses(project, station).size());
    auto ofStation = [&](const auto& container) {
        return static_cast<int>(
            std::count_if(container.begin(), container.end(), [&](const auto& item) {
                if constexpr (requires { item.first; })
                    return item.first.unit == station;
                else
                    return item.unit == station;
            }));
    };
    return count + ofStation(project.variableDescriptions) + ofStation(project.exportedVariables) +
           ofStation(project.remanentVariables);
}

} // namespace

int removedByChange(const Project& project, const UnitSettings& settings) {
    Project changed = project;
    if (changeUnit(changed, settings))
        return 0;
    return unitItems(project, settings.station) - unitItems(changed, settings.station);
}

void removeUnit(Project& project, int station) {
    forEachDeclarationList(project.program, [&](std::vector<Line>& lines) {
        std::erase_if(lines, [&](const Line& line) { return stationOf(line) == station; });
    });
    std::erase_if(project.program.preamble, [&](const Line& line) {
        auto* name = declarationOf<lang::NameDeclaration>(line);
        return name && belongsToStation(name->variable.address, station);
    });
    std::erase_if(project.program.units,
                  [&](const lang::UnitProgram& unit) { return unit.station() == station; });
    project.unitDescriptions.erase(station);
    project.idfixProg.erase(station);
    project.asiOptions.erase(station);
    project.canCycleMs.erase(station);
    project.externalComm.erase(station);
    std::erase_if(project.variableDescriptions,
                  [&](const auto& entry) { return belongsToStation(entry.first, station); });
    std::erase_if(project.exportedVariables,
                  [&](const lang::Address& a) { return belongsToStation(a, station); });
    std::erase_if(project.remanentVariables,
                  [&](const lang::Address& a) { return belongsToStation(a, station); });
    tidyBlankLines(project.program);
}

} // namespace rs::project
