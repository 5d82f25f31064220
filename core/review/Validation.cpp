// SPDX-License-Identifier: GPL-3.0-or-later
#include "Validation.h"

#include "compiler/Signature.h"

#include <map>
#include <set>

namespace rs::review {

namespace {

std::uint32_t fromHex(const std::string& text) {
    return static_cast<std::uint32_t>(std::stoul(text, nullptr, 16));
}

} // namespace

project::Baseline validatedBaseline(const project::Project& project,
                                    const compiler::CompileResult& compiled, std::string date,
                                    std::string by, std::string comment) {
    project::Baseline baseline{
        std::move(date), std::move(by), std::move(comment), compiled.projectSignature, {}};
    for (const auto& unit : compiled.signatures)
        baseline.units[unit.station].signature = unit.value;
    for (const auto& [step, crcs] : fingerprints(networksByStep(project))) {
        const auto& [station, sequence, number] = step;
        auto& networks = baseline.units[station].networks[{sequence, number}];
        for (const auto& crc : crcs)
            networks.push_back(fromHex(crc));
    }
    return baseline;
}

ProjectDiff changesSinceValidation(const project::Project& project,
                                   const compiler::CompileResult& compiled) {
    const project::Baseline& baseline = *project.baseline;
    ProjectDiff diff;
    diff.oldSignature = baseline.signature;
    diff.newSignature = compiled.projectSignature;
    StepNetworks validated;
    for (const auto& [station, unit] : baseline.units)
        for (const auto& [step, crcs] : unit.networks) {
            auto& texts = validated[{station, step.first, step.second}];
            for (const std::uint32_t crc : crcs)
                texts.push_back(compiler::signatureText(crc));
        }
    diff.networks = networkDifferences(validated, fingerprints(networksByStep(project)));
    std::map<int, std::uint32_t> now;
    for (const auto& unit : compiled.signatures)
        now[unit.station] = unit.value;
    std::set<int> stations;
    for (const auto& entry : baseline.units)
        stations.insert(entry.first);
    for (const auto& entry : now)
        stations.insert(entry.first);
    for (const int station : stations) {
        const auto old = baseline.units.find(station);
        const auto current = now.find(station);
        if (old == baseline.units.end())
            diff.units.push_back({station, "unit: added"});
        else if (current == now.end())
            diff.units.push_back({station, "unit: removed"});
        if (old == baseline.units.end() || current == now.end() ||
            old->second.signature != current->second)
            diff.changedStations.push_back(station);
    }
    return diff;
}

} // namespace rs::review
