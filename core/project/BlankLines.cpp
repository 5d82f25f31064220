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

} // namespace

void tidyUnitBlankLines(lang::Document& document, int station) {
    for (std::size_t i = 0; i < document.units.size(); ++i) {
        auto& unit = document.units[i];
        if (unit.station() != station)
            continue;
        collapseRuns(unit.declarations, false);
        for (auto& step : unit.steps)
            collapseRuns(step.lines, false);
        auto& last = unit.steps.empty() ? unit.declarations : unit.steps.back().lines;
        if (i + 1 == document.units.size() && !last.empty() && isBlank(last.back()))
            last.pop_back();
    }
}

void tidyBlankLines(lang::Document& document) {
    collapseRuns(document.preamble, true);
    for (auto& unit : document.units) {
        collapseRuns(unit.declarations, false);
        for (auto& step : unit.steps)
            collapseRuns(step.lines, false);
    }
    std::vector<lang::Line>* last = &document.preamble;
    if (!document.units.empty()) {
        auto& unit = document.units.back();
        last = unit.steps.empty() ? &unit.declarations : &unit.steps.back().lines;
    }
    if (!last->empty() && isBlank(last->back()))
        last->pop_back();
}

} // namespace rs::project
