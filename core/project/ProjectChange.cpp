// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectChange.h"

#include <stdexcept>

namespace rs::project {

namespace {

bool sameStations(const std::vector<lang::UnitProgram>& a,
                  const std::vector<lang::UnitProgram>& b) {
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].station() != b[i].station() || !(a[i].header == b[i].header))
            return false;
    return true;
}

} // namespace

ProjectChange::Records ProjectChange::recordsOf(const Project& project) {
    return {project.description,       project.includeSource,     project.unitDescriptions,
            project.idfixProg,         project.asiOptions,        project.canCycleMs,
            project.externalComm,      project.gateways,          project.variableDescriptions,
            project.exportedVariables, project.remanentVariables, project.libraries,
            project.baseline,          project.protection};
}

void ProjectChange::setRecords(Project& project, const Records& records) {
    project.description = records.description;
    project.includeSource = records.includeSource;
    project.unitDescriptions = records.unitDescriptions;
    project.idfixProg = records.idfixProg;
    project.asiOptions = records.asiOptions;
    project.canCycleMs = records.canCycleMs;
    project.externalComm = records.externalComm;
    project.gateways = records.gateways;
    project.variableDescriptions = records.variableDescriptions;
    project.exportedVariables = records.exportedVariables;
    project.remanentVariables = records.remanentVariables;
    project.libraries = records.libraries;
    project.baseline = records.baseline;
    project.protection = records.protection;
}

ProjectChange ProjectChange::between(const Project& before, const Project& after) {
    return between(before, after, std::nullopt);
}

ProjectChange ProjectChange::ofUnitCode(const Project& before, const Project& after, int station) {
    if (sameStations(before.program.units, after.program.units))
        return between(before, after, station);
    // Units added or removed: the whole program, with the other units' code.
    Project whole = after;
    for (std::size_t i = 0; i < whole.program.units.size(); ++i)
        if (const int other = whole.program.units[i].station(); other != station)
            for (const auto& unit : before.program.units)
                if (unit.station() == other)
                    whole.program.units[i].steps = unit.steps;
    return between(before, whole, std::nullopt);
}

ProjectChange ProjectChange::between(const Project& before, const Project& after,
                                     std::optional<int> onlyCodeOf) {
    ProjectChange change;
    Records was = recordsOf(before);
    Records is = recordsOf(after);
    if (!(was == is))
        change.m_records = Replacement<Records>{std::move(was), std::move(is)};
    if (!(before.program.preamble == after.program.preamble))
        change.m_preamble = {before.program.preamble, after.program.preamble};

    const auto& unitsBefore = before.program.units;
    const auto& unitsAfter = after.program.units;
    if (!sameStations(unitsBefore, unitsAfter)) {
        change.m_units = {unitsBefore, unitsAfter};
        return change;
    }
    for (std::size_t i = 0; i < unitsBefore.size(); ++i) {
        const auto& was = unitsBefore[i];
        const auto& is = unitsAfter[i];
        if (onlyCodeOf && was.station() != *onlyCodeOf)
            continue; // its code is not in `after`, and it is unchanged
        UnitChange unit;
        unit.index = i;
        if (!(was.declarations == is.declarations))
            unit.declarations = {was.declarations, is.declarations};
        if (was.steps.size() != is.steps.size()) {
            unit.allSteps = {was.steps, is.steps};
        } else {
            for (std::size_t s = 0; s < was.steps.size(); ++s)
                if (!(was.steps[s] == is.steps[s]))
                    unit.steps.push_back(stepChange(s, was.steps[s], is.steps[s]));
        }
        if (unit.declarations || unit.allSteps || !unit.steps.empty())
            change.m_unitChanges.push_back(std::move(unit));
    }
    return change;
}

ProjectChange::StepChange ProjectChange::stepChange(std::size_t index, const lang::Step& before,
                                                    const lang::Step& after) {
    const auto& was = before.lines;
    const auto& is = after.lines;
    std::size_t first = 0;
    while (first < was.size() && first < is.size() && was[first] == is[first])
        ++first;
    std::size_t same = 0; // at the end
    while (same < was.size() - first && same < is.size() - first &&
           was[was.size() - 1 - same] == is[is.size() - 1 - same])
        ++same;
    const auto run = [&](const std::vector<lang::Line>& lines) {
        return std::vector<lang::Line>(lines.begin() + static_cast<std::ptrdiff_t>(first),
                                       lines.end() - static_cast<std::ptrdiff_t>(same));
    };
    return {index,
            {{before.address, before.comment, before.location, {}},
             {after.address, after.comment, after.location, {}}},
            first,
            {run(was), run(is)}};
}

void ProjectChange::changeStep(lang::Step& step, const StepChange& change, bool forward) {
    const lang::Step& header = forward ? change.header.after : change.header.before;
    const auto& removed = forward ? change.lines.before : change.lines.after;
    const auto& added = forward ? change.lines.after : change.lines.before;
    step.address = header.address;
    step.comment = header.comment;
    step.location = header.location;
    const auto at = step.lines.begin() + static_cast<std::ptrdiff_t>(change.firstLine);
    const auto kept = step.lines.erase(at, at + static_cast<std::ptrdiff_t>(removed.size()));
    step.lines.insert(kept, added.begin(), added.end());
}

ProjectChange ProjectChange::ofStepLines(const Project& before, std::size_t unit, std::size_t step,
                                         std::size_t first, std::size_t removed,
                                         std::vector<lang::Line> added) {
    const lang::Step& was = before.program.units.at(unit).steps.at(step);
    if (first > was.lines.size() || removed > was.lines.size() - first)
        throw std::out_of_range("ProjectChange::ofStepLines: the run is not in the step");
    const auto from = was.lines.begin() + static_cast<std::ptrdiff_t>(first);
    std::vector<lang::Line> old(from, from + static_cast<std::ptrdiff_t>(removed));
    ProjectChange change;
    if (old == added)
        return change;
    const lang::Step header{was.address, was.comment, was.location, {}};
    UnitChange unitChange;
    unitChange.index = unit;
    unitChange.steps.push_back({step, {header, header}, first, {std::move(old), std::move(added)}});
    change.m_unitChanges.push_back(std::move(unitChange));
    return change;
}

bool ProjectChange::empty() const {
    return !m_records && !m_preamble && !m_units && m_unitChanges.empty();
}

std::optional<StepLinesChange> ProjectChange::stepLines(bool forward) const {
    if (m_records || m_preamble || m_units || m_unitChanges.size() != 1)
        return std::nullopt;
    const UnitChange& unit = m_unitChanges.front();
    if (unit.declarations || unit.allSteps || unit.steps.size() != 1)
        return std::nullopt;
    const StepChange& step = unit.steps.front();
    if (!(step.header.before == step.header.after))
        return std::nullopt;
    return StepLinesChange{unit.index, step.index, step.firstLine,
                           forward ? step.lines.before : step.lines.after,
                           forward ? step.lines.after : step.lines.before};
}

void ProjectChange::apply(Project& project) const {
    change(project, true);
}

void ProjectChange::revert(Project& project) const {
    change(project, false);
}

void ProjectChange::change(Project& project, bool forward) const {
    auto pick = [forward](const auto& replacement) -> const auto& {
        return forward ? replacement.after : replacement.before;
    };
    if (m_records)
        setRecords(project, pick(*m_records));
    if (m_preamble)
        project.program.preamble = pick(*m_preamble);
    if (m_units) {
        project.program.units = pick(*m_units);
        return;
    }
    for (const auto& unit : m_unitChanges) {
        auto& program = project.program.units.at(unit.index);
        if (unit.declarations)
            program.declarations = pick(*unit.declarations);
        if (unit.allSteps)
            program.steps = pick(*unit.allSteps);
        for (const auto& step : unit.steps)
            changeStep(program.steps.at(step.index), step, forward);
    }
}

} // namespace rs::project
