// SPDX-License-Identifier: GPL-3.0-or-later
#include "NetworkDiff.h"

#include "NetworkMeaning.h"

#include <cstdio>
#include <map>
#include <set>

namespace rs::review {

namespace {

using StepKey = std::pair<int, int>; // sequence, step

std::map<StepKey, const lang::Step*> stepsOf(const project::Project& project, int station) {
    std::map<StepKey, const lang::Step*> steps;
    for (const auto& unit : project.program.units)
        if (unit.station() == station)
            for (const auto& step : unit.steps)
                steps.emplace(StepKey{step.address.sequence, step.address.step}, &step);
    return steps;
}

std::vector<std::string> meanings(const project::Project& project, int station,
                                  const lang::Step* step) {
    std::vector<std::string> texts;
    if (step)
        for (const auto& network : project::networksOf(*step))
            texts.push_back(networkMeaning(project.program, station, network));
    return texts;
}

const char* changeWord(Pairing::Kind kind) {
    switch (kind) {
    case Pairing::Added:
        return "added";
    case Pairing::Removed:
        return "removed";
    case Pairing::Same:
        return "unchanged";
    case Pairing::Changed:
        break;
    }
    return "changed";
}

} // namespace

std::string NetworkDifference::describe() const {
    char station[8];
    std::snprintf(station, sizeof station, "%02d", this->station);
    return "Pluto " + std::string(station) + ' ' + lang::toString(step) + " network " +
           std::to_string(number) + ": " + changeWord(change);
}

std::vector<NetworkDifference> networkDifferences(const project::Project& before,
                                                  const project::Project& after) {
    std::set<int> stations;
    for (const auto* project : {&before, &after})
        for (const auto& unit : project->program.units)
            stations.insert(unit.station());
    std::vector<NetworkDifference> differences;
    for (const int station : stations) {
        const auto oldSteps = stepsOf(before, station);
        const auto newSteps = stepsOf(after, station);
        std::set<StepKey> keys;
        for (const auto* steps : {&oldSteps, &newSteps})
            for (const auto& entry : *steps)
                keys.insert(entry.first);
        for (const StepKey& key : keys) {
            const auto oldStep = oldSteps.find(key);
            const auto newStep = newSteps.find(key);
            const lang::StepAddress address{station, key.first, key.second};
            for (const Pairing& pairing :
                 align(meanings(before, station,
                                oldStep == oldSteps.end() ? nullptr : oldStep->second),
                       meanings(after, station,
                                newStep == newSteps.end() ? nullptr : newStep->second))) {
                if (pairing.kind == Pairing::Same)
                    continue;
                const int index =
                    pairing.kind == Pairing::Removed ? pairing.oldIndex : pairing.newIndex;
                differences.push_back({station, address, index + 1, pairing.kind});
            }
        }
    }
    return differences;
}

} // namespace rs::review
