// SPDX-License-Identifier: GPL-3.0-or-later
#include "BlankLines.h"

namespace rs::project {

namespace {

bool isBlank(const lang::Line& line) {
    return std::holds_alternative<lang::BlankLine>(line.body) && !line.comment;
}

// A run of blank lines can only form inside one list of lines: between two
// lists stands a unit header or a step header.
void collapseRuns(std::vector<lang::Line>& lines, bool atDocumentStart) {
    std::vector<lang::Line> kept;
    kept.reserve(lines.size());
    for (auto& line : lines) {
        if (isBlank(line) && (kept.empty() ? atDocumentStart : isBlank(kept.back())))
            continue;
        kept.push_back(std::move(line));
    }
    lines = std::move(kept);
}

// A unit's lists of lines; its last line is dropped when blank if the unit
// ends the document.
void tidyUnit(lang::UnitProgram& unit, bool lastInDocument) {
    collapseRuns(unit.declarations, false);
    for (auto& step : unit.steps)
        collapseRuns(step.lines, false);
    auto& last = unit.steps.empty() ? unit.declarations : unit.steps.back().lines;
    if (lastInDocument && !last.empty() && isBlank(last.back()))
        last.pop_back();
}

} // namespace

void tidyUnitBlankLines(lang::Document& document, int station) {
    for (std::size_t i = 0; i < document.units.size(); ++i)
        if (document.units[i].station() == station)
            tidyUnit(document.units[i], i + 1 == document.units.size());
}

void tidyBlankLines(lang::Document& document) {
    collapseRuns(document.preamble, true);
    for (std::size_t i = 0; i < document.units.size(); ++i)
        tidyUnit(document.units[i], i + 1 == document.units.size());
    if (document.units.empty() && !document.preamble.empty() && isBlank(document.preamble.back()))
        document.preamble.pop_back();
}

} // namespace rs::project
