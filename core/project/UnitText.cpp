// SPDX-License-Identifier: GPL-3.0-or-later
#include "UnitText.h"

#include "BlankLines.h"
#include "ProjectFile.h"
#include "UnitSettings.h"
#include "lang/Printer.h"

#include <algorithm>
#include <functional>

namespace rs::project {

namespace {

std::string twoDigits(int station) {
    return (station < 10 ? "0" : "") + std::to_string(station);
}

bool endsWithBlank(const lang::UnitProgram& unit) {
    const auto& lines = unit.steps.empty() ? unit.declarations : unit.steps.back().lines;
    return !lines.empty() && std::holds_alternative<lang::BlankLine>(lines.back().body);
}

// Everything of the project but the units' code: what the unit's text is read against.
Project headOf(const Project& project) {
    Project head;
    head.program.preamble = project.program.preamble;
    head.description = project.description;
    head.includeSource = project.includeSource;
    head.unitDescriptions = project.unitDescriptions;
    head.idfixProg = project.idfixProg;
    head.asiOptions = project.asiOptions;
    head.canCycleMs = project.canCycleMs;
    head.externalComm = project.externalComm;
    head.gateways = project.gateways;
    head.variableDescriptions = project.variableDescriptions;
    head.exportedVariables = project.exportedVariables;
    head.remanentVariables = project.remanentVariables;
    return head;
}

// Blank lines at the top of the unit's text join the preamble's; they change nothing.
bool samePreamble(const std::vector<lang::Line>& a, const std::vector<lang::Line>& b) {
    auto nonBlank = [](const std::vector<lang::Line>& lines) {
        std::vector<const lang::Line*> kept;
        for (const auto& line : lines)
            if (!std::holds_alternative<lang::BlankLine>(line.body))
                kept.push_back(&line);
        return kept;
    };
    const auto x = nonBlank(a);
    const auto y = nonBlank(b);
    return std::equal(x.begin(), x.end(), y.begin(), y.end(),
                      [](const lang::Line* l, const lang::Line* r) { return *l == *r; });
}

int lineCount(std::string_view text) {
    return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

} // namespace

std::string unitText(const Project& project, int station) {
    for (const auto& unit : project.program.units) {
        if (unit.station() != station)
            continue;
        lang::Document alone;
        alone.units.push_back(unit);
        tidyBlankLines(alone); // the blank line before the next unit is not part of it
        return lang::print(alone);
    }
    return "! pgm_pluto:" + twoDigits(station) + "\n";
}

Project withOnlyCodeOf(const Project& project, int station) {
    Project part = headOf(project);
    part.libraries = project.libraries;
    part.baseline = project.baseline;
    part.protection = project.protection;
    for (const auto& unit : project.program.units) {
        lang::UnitProgram& copy = part.program.units.emplace_back();
        copy.header = unit.header;
        copy.declarations = unit.declarations;
        if (unit.station() == station)
            copy.steps = unit.steps;
    }
    return part;
}

namespace {

// `base`: the project the unit's code goes into, the project itself or a part of it.
UnitTextResult readUnitInto(const Project& project, int station, std::string_view text,
                            const std::function<Project()>& base) {
    const std::string head = writeProject(headOf(project));
    const int offset = lineCount(head);
    std::string whole = head;
    whole += text;
    ProjectReadResult read = readProject(whole);

    UnitTextResult result;
    for (auto diagnostic : read.diagnostics) {
        if (diagnostic.line > offset) {
            diagnostic.line -= offset;
        } else {
            diagnostic.message = "in the project's declarations: " + diagnostic.message;
            diagnostic.line = 0;
        }
        result.diagnostics.push_back(std::move(diagnostic));
    }
    auto error = [&](int line, std::string message) {
        result.diagnostics.push_back({lang::Severity::Error, line, 1, std::move(message)});
    };
    const std::string header = "'! pgm_pluto:" + twoDigits(station) + "'";
    auto& units = read.project.program.units;
    if (!samePreamble(read.project.program.preamble, project.program.preamble))
        error(1, "the code of unit " + std::to_string(station) + " starts with its line " + header +
                     "; nothing stands before it");
    else if (units.empty())
        error(1, "the code of unit " + std::to_string(station) + " starts with its line " + header);
    else if (units.front().station() != station)
        error(1, "this is the code of unit " + std::to_string(station) + "; its first line is " +
                     header);
    for (std::size_t i = 1; i < units.size(); ++i)
        error(units[i].header.location.line - offset,
              "the code of another unit cannot start here; add units with New Pluto");
    if (!result.ok()) {
        std::stable_sort(result.diagnostics.begin(), result.diagnostics.end(),
                         [](const auto& a, const auto& b) { return a.line < b.line; });
        result.project = base();
        return result;
    }

    result.project = base();
    lang::UnitProgram& target = programOf(result.project, station);
    const bool separated = endsWithBlank(target);
    target = std::move(units.front());
    if (separated)
        if (auto& lines = target.steps.empty() ? target.declarations : target.steps.back().lines;
            lines.empty() || !std::holds_alternative<lang::BlankLine>(lines.back().body))
            lines.push_back({lang::BlankLine{}, std::nullopt, {}});
    result.project.description = read.project.description;
    result.project.includeSource = read.project.includeSource;
    result.project.unitDescriptions = std::move(read.project.unitDescriptions);
    result.project.idfixProg = std::move(read.project.idfixProg);
    result.project.asiOptions = std::move(read.project.asiOptions);
    result.project.canCycleMs = std::move(read.project.canCycleMs);
    result.project.externalComm = std::move(read.project.externalComm);
    result.project.gateways = std::move(read.project.gateways);
    result.project.variableDescriptions = std::move(read.project.variableDescriptions);
    result.project.exportedVariables = std::move(read.project.exportedVariables);
    result.project.remanentVariables = std::move(read.project.remanentVariables);
    tidyUnitBlankLines(result.project.program, station);
    return result;
}

} // namespace

UnitTextResult readUnitText(const Project& project, int station, std::string_view text) {
    return readUnitInto(project, station, text, [&] { return project; });
}

UnitTextResult readUnitCode(const Project& project, int station, std::string_view text) {
    return readUnitInto(project, station, text, [&] { return withOnlyCodeOf(project, station); });
}

} // namespace rs::project
