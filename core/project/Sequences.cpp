// SPDX-License-Identifier: GPL-3.0-or-later
#include "Sequences.h"

#include "BlankLines.h"
#include "UnitSettings.h"

#include <algorithm>
#include <set>

namespace rs::project {

std::vector<int> sequencesOf(const Project& project, int station) {
    std::set<int> sequences;
    for (const auto& unit : project.program.units)
        if (unit.station() == station)
            for (const auto& step : unit.steps)
                if (step.address.sequence >= kFirstSequence &&
                    step.address.sequence <= kLastSequence)
                    sequences.insert(step.address.sequence);
    return {sequences.begin(), sequences.end()};
}

std::vector<int> freeSequences(const Project& project, int station) {
    const std::vector<int> used = sequencesOf(project, station);
    std::vector<int> free;
    for (int sequence = kFirstSequence; sequence <= kLastSequence; ++sequence)
        if (std::find(used.begin(), used.end(), sequence) == used.end())
            free.push_back(sequence);
    return free;
}

std::optional<std::string> addSequence(Project& project, int station, int sequence) {
    if (sequence < kFirstSequence || sequence > kLastSequence)
        return "a sequence is numbered 1-9";
    const std::vector<int> used = sequencesOf(project, station);
    if (std::find(used.begin(), used.end(), sequence) != used.end())
        return "unit " + std::to_string(station) + " already has sequence " +
               std::to_string(sequence);
    auto& steps = programOf(project, station).steps;
    auto at = std::find_if(steps.begin(), steps.end(), [&](const lang::Step& step) {
        return step.address.sequence > sequence;
    });
    // The step before the new one ends with a blank line, as steps of
    // different sequences are written apart.
    if (at != steps.begin()) {
        auto& lines = (at - 1)->lines;
        if (lines.empty() || !std::holds_alternative<lang::BlankLine>(lines.back().body))
            lines.push_back({lang::BlankLine{}, std::nullopt, {}});
    }
    lang::Step step{{station, sequence, 0}, std::nullopt, {}, {}};
    if (at != steps.end())
        step.lines.push_back({lang::BlankLine{}, std::nullopt, {}});
    steps.insert(at, std::move(step));
    tidyBlankLines(project.program);
    return std::nullopt;
}

AddedStep addStep(Project& project, int station, int sequence) {
    if (sequence < 0 || sequence > kLastSequence)
        return {-1, "a sequence is numbered 0-9"};
    auto& steps = programOf(project, station).steps;
    auto last = std::find_if(steps.rbegin(), steps.rend(), [&](const lang::Step& step) {
        return step.address.sequence == sequence;
    });
    if (last == steps.rend()) {
        if (auto refusal = addSequence(project, station, sequence))
            return {-1, *refusal};
        return {0, {}};
    }
    const int number = last->address.step + 1;
    steps.insert(last.base(), lang::Step{{station, sequence, number}, std::nullopt, {}, {}});
    tidyBlankLines(project.program);
    return {number, {}};
}

} // namespace rs::project
