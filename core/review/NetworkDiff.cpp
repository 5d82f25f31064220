// SPDX-License-Identifier: GPL-3.0-or-later
#include "NetworkDiff.h"

#include "EditorNetworks.h"
#include "NetworkMeaning.h"
#include "compiler/ImageCodec.h"
#include "compiler/Signature.h"

#include <cstdio>
#include <map>
#include <set>

namespace rs::review {

namespace {

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

StepNetworks networksByStep(const project::Project& project) {
    StepNetworks steps;
    for (const auto& unit : project.program.units) {
        const int station = unit.station();
        for (const auto& step : unit.steps) {
            auto& texts = steps[{station, step.address.sequence, step.address.step}];
            for (const auto& network : editorNetworks(step))
                texts.push_back(networkMeaning(project.program, station, network));
        }
    }
    return steps;
}

StepNetworks fingerprints(const StepNetworks& networks) {
    StepNetworks crcs;
    for (const auto& [step, texts] : networks) {
        auto& out = crcs[step];
        for (const auto& text : texts)
            out.push_back(compiler::signatureText(compiler::crc32(text)));
    }
    return crcs;
}

std::vector<NetworkDifference> networkDifferences(const StepNetworks& before,
                                                  const StepNetworks& after) {
    std::set<std::tuple<int, int, int>> steps;
    for (const auto* side : {&before, &after})
        for (const auto& entry : *side)
            steps.insert(entry.first);
    static const std::vector<std::string> kNone;
    std::vector<NetworkDifference> differences;
    for (const auto& key : steps) {
        const auto old = before.find(key);
        const auto now = after.find(key);
        const auto& [station, sequence, step] = key;
        for (const Pairing& pairing : align(old == before.end() ? kNone : old->second,
                                            now == after.end() ? kNone : now->second)) {
            if (pairing.kind == Pairing::Same)
                continue;
            const int index =
                pairing.kind == Pairing::Removed ? pairing.oldIndex : pairing.newIndex;
            differences.push_back({station, lang::StepAddress{station, sequence, step}, index + 1,
                                   pairing.oldIndex + 1, pairing.kind});
        }
    }
    return differences;
}

std::vector<NetworkDifference> networkDifferences(const project::Project& before,
                                                  const project::Project& after) {
    return networkDifferences(networksByStep(before), networksByStep(after));
}

} // namespace rs::review
