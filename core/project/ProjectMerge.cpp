// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectMerge.h"

#include "lang/OperandWalk.h"
#include "lang/SymbolicName.h"

#include <algorithm>
#include <map>
#include <set>

namespace rs::project {

namespace {

const lang::NameDeclaration* nameDeclared(const lang::Line& line) {
    const auto* declaration = std::get_if<lang::Declaration>(&line.body);
    return declaration ? std::get_if<lang::NameDeclaration>(&declaration->body) : nullptr;
}

struct Named {
    std::string spelling;
    std::vector<lang::Address> addresses;
};

// Every symbolic name of a program, global or local, by its folded form.
std::map<std::string, Named> namesOf(const lang::Document& program) {
    std::map<std::string, Named> names;
    auto scan = [&](const std::vector<lang::Line>& lines) {
        for (const lang::Line& line : lines)
            if (const lang::NameDeclaration* name = nameDeclared(line)) {
                Named& named = names[lang::foldName(name->name)];
                if (named.spelling.empty())
                    named.spelling = name->name;
                named.addresses.push_back(name->variable.address);
            }
    };
    scan(program.preamble);
    for (const lang::UnitProgram& unit : program.units)
        scan(unit.declarations);
    return names;
}

std::string addressList(const std::vector<lang::Address>& addresses) {
    std::string text;
    for (const lang::Address& address : addresses)
        text += (text.empty() ? "" : ", ") + lang::toString(address);
    return text;
}

// The folded name an operand is written with: "Counter.3" and "Speed.Lo" are
// uses of Counter and Speed.
std::string foldedBase(const std::string& name) {
    std::string folded = lang::foldName(name);
    if (const auto dot = folded.rfind('.'); dot != std::string::npos && dot > 0)
        folded.resize(dot);
    return folded;
}

// Each global declaration of a shared name moves to the code of the unit of
// the variable it names, so that in that unit's code the name means that
// variable; a unit without code has no place for it, and it is dropped (a
// global name and a local one alike would be an error). Uses in other units,
// which no longer see the name, are written as addresses.
void localise(lang::Document& program, const std::set<std::string>& shared) {
    std::map<int, lang::UnitProgram*> units;
    for (lang::UnitProgram& unit : program.units)
        units[unit.station()] = &unit;
    std::vector<lang::Line> kept;
    for (lang::Line& line : program.preamble) {
        const lang::NameDeclaration* name = nameDeclared(line);
        if (!name || shared.count(lang::foldName(name->name)) == 0)
            kept.push_back(std::move(line));
        else if (const auto owner = units.find(name->variable.address.unit); owner != units.end())
            owner->second->declarations.push_back(std::move(line));
    }
    program.preamble = std::move(kept);
    for (lang::UnitProgram& unit : program.units) {
        std::set<std::string> declared;
        for (const lang::Line& line : unit.declarations)
            if (const lang::NameDeclaration* name = nameDeclared(line))
                declared.insert(lang::foldName(name->name));
        for (lang::Step& step : unit.steps)
            for (lang::Line& line : step.lines)
                if (auto* statement = std::get_if<lang::Statement>(&line.body))
                    lang::forEachOperand(*statement, [&](lang::Operand& operand) {
                        const std::string used = foldedBase(operand.name);
                        if (operand.isName() && shared.count(used) > 0 && declared.count(used) == 0)
                            operand.name = {};
                    });
    }
}

} // namespace

MergeResult mergeProjects(const Project& into, const Project& other, bool ignoreNameConflicts) {
    MergeResult result;
    const std::vector<int> ours = into.stations();
    for (const int station : other.stations())
        if (std::binary_search(ours.begin(), ours.end(), station))
            result.conflicts.push_back("station " + std::to_string(station) +
                                       " is in both projects");
    for (const auto& [node, gateway] : other.gateways)
        if (into.gateways.count(node))
            result.conflicts.push_back("gateway node " + std::to_string(node) +
                                       " is in both projects");
    const bool stationsClash = !result.conflicts.empty();
    const std::map<std::string, Named> ourNames = namesOf(into.program);
    std::set<std::string> shared;
    for (const auto& [key, named] : namesOf(other.program))
        if (const auto same = ourNames.find(key); same != ourNames.end()) {
            shared.insert(key);
            std::vector<lang::Address> addresses = same->second.addresses;
            addresses.insert(addresses.end(), named.addresses.begin(), named.addresses.end());
            result.conflicts.push_back("the name '" + same->second.spelling +
                                       "' is in both projects (" + addressList(addresses) + ")");
        }
    if (stationsClash || (!shared.empty() && !ignoreNameConflicts))
        return result;

    Project merged = into;
    for (const lang::Line& line : other.program.preamble)
        if (!std::holds_alternative<lang::Directive>(line.body)) // $name and the like are ours
            merged.program.preamble.push_back(line);
    for (const lang::UnitProgram& unit : other.program.units)
        merged.program.units.push_back(unit);
    std::stable_sort(merged.program.units.begin(), merged.program.units.end(),
                     [](const lang::UnitProgram& a, const lang::UnitProgram& b) {
                         return a.station() < b.station();
                     });
    merged.unitDescriptions.insert(other.unitDescriptions.begin(), other.unitDescriptions.end());
    merged.idfixProg.insert(other.idfixProg.begin(), other.idfixProg.end());
    merged.asiOptions.insert(other.asiOptions.begin(), other.asiOptions.end());
    merged.canCycleMs.insert(other.canCycleMs.begin(), other.canCycleMs.end());
    merged.externalComm.insert(other.externalComm.begin(), other.externalComm.end());
    merged.gateways.insert(other.gateways.begin(), other.gateways.end());
    merged.variableDescriptions.insert(other.variableDescriptions.begin(),
                                       other.variableDescriptions.end());
    merged.exportedVariables.insert(other.exportedVariables.begin(), other.exportedVariables.end());
    merged.remanentVariables.insert(other.remanentVariables.begin(), other.remanentVariables.end());
    // None named means every library found (Project::libraries), which stays so.
    if (!merged.libraries.empty())
        for (const std::string& library : other.libraries)
            if (std::find(merged.libraries.begin(), merged.libraries.end(), library) ==
                merged.libraries.end())
                merged.libraries.push_back(library);
    localise(merged.program, shared);
    result.merged = std::move(merged);
    return result;
}

} // namespace rs::project
