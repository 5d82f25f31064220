// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectDiff.h"

#include "compiler/Signature.h"
#include "project/ProjectFile.h"

#include <cstdio>
#include <map>
#include <set>

namespace rs::review {

namespace {

std::string unitName(int station) {
    char text[16];
    std::snprintf(text, sizeof text, "Pluto %02d", station);
    return text;
}

std::map<int, std::uint32_t> byStation(const std::vector<compiler::UnitSignature>& signatures) {
    std::map<int, std::uint32_t> map;
    for (const auto& signature : signatures)
        map[signature.station] = signature.value;
    return map;
}

} // namespace

std::vector<std::string> ProjectDiff::lines() const {
    std::set<int> stations;
    for (const auto& unit : units)
        stations.insert(unit.station);
    for (const auto& network : networks)
        stations.insert(network.station);
    std::vector<std::string> out;
    for (const int station : stations) {
        for (const auto& unit : units)
            if (unit.station == station)
                out.push_back(unit.describe());
        for (const auto& network : networks)
            if (network.station == station)
                out.push_back(network.describe());
    }
    out.push_back(verdict());
    return out;
}

std::string ProjectDiff::verdict() const {
    if (!behaviourChanged())
        return textChanged ? "no change in behaviour; only the text changed"
                           : "no change in behaviour";
    std::string text = "behaviour changed";
    for (std::size_t i = 0; i < changedStations.size(); ++i)
        text += (i ? ", " : " in ") + unitName(changedStations[i]);
    return text + " (project signature " + compiler::signatureText(newSignature) + ", was " +
           compiler::signatureText(oldSignature) + ")";
}

ProjectDiff diffProjects(const project::Project& before, const compiler::CompileResult& oldCompiled,
                         const project::Project& after,
                         const compiler::CompileResult& newCompiled) {
    ProjectDiff diff;
    diff.units = unitDifferences(before, after);
    diff.networks = networkDifferences(before, after);
    diff.oldSignature = oldCompiled.projectSignature;
    diff.newSignature = newCompiled.projectSignature;
    diff.textChanged = project::writeProject(before) != project::writeProject(after);
    const auto oldUnits = byStation(oldCompiled.signatures);
    const auto newUnits = byStation(newCompiled.signatures);
    std::set<int> stations;
    for (const auto* units : {&oldUnits, &newUnits})
        for (const auto& entry : *units)
            stations.insert(entry.first);
    for (const int station : stations) {
        const auto old = oldUnits.find(station);
        const auto now = newUnits.find(station);
        if (old == oldUnits.end() || now == newUnits.end() || old->second != now->second)
            diff.changedStations.push_back(station);
    }
    return diff;
}

} // namespace rs::review
