// SPDX-License-Identifier: GPL-3.0-or-later
#include "LadderPage.h"

#include "document/ProjectDocument.h"
#include "ladder/TextToLadder.h"
#include "lang/Parser.h"
#include "project/UnitText.h"

#include <algorithm>

namespace rs::ui {

namespace {

// Element numbers (pre-order from 1) and columns of a condition's elements.
void numberElements(const ladder::Circuit& circuit, std::uint16_t& number,
                    std::vector<std::pair<std::uint16_t, int>>& columns) {
    const std::uint16_t mine = number++;
    if (circuit.isElement()) {
        columns.emplace_back(mine, circuit.location.column);
        return;
    }
    for (const auto& part : circuit.parts)
        numberElements(part, number, columns);
}

} // namespace

void LadderPage::setDiagnostics(const lang::Diagnostics& diagnostics) {
    m_drawing.problems.clear();
    if (!m_document || diagnostics.empty()) {
        repaintItems();
        return;
    }
    // Statements numbered in file order, as the compiler numbers them, with
    // the lines and columns of the unit's text.
    const lang::ParseResult parsed =
        lang::parse(project::unitText(m_document->project(), m_station));
    struct Place {
        int line;
        std::uint32_t statement;
        std::vector<std::pair<std::uint16_t, int>> columns;
    };
    std::vector<Place> places;
    std::uint32_t number = 0;
    for (const auto& unit : parsed.document.units)
        for (const auto& step : unit.steps)
            for (const auto& line : step.lines)
                if (const auto* statement = std::get_if<lang::Statement>(&line.body)) {
                    Place place{statement->location.line, number++, {}};
                    if (statement->condition) {
                        std::uint16_t element = 1;
                        numberElements(ladder::toCircuit(*statement->condition), element,
                                       place.columns);
                    }
                    places.push_back(std::move(place));
                }
    for (const auto& diagnostic : diagnostics) {
        const auto place = std::find_if(places.begin(), places.end(),
                                        [&](const Place& p) { return p.line == diagnostic.line; });
        if (place == places.end())
            continue;
        std::uint16_t element = 0;
        for (const auto& [candidate, column] : place->columns)
            if (column <= diagnostic.column)
                element = candidate;
        QString& text = m_drawing.problems[{place->statement, element}];
        if (!text.isEmpty())
            text += QLatin1Char('\n');
        text += QString::fromStdString(diagnostic.message);
    }
    repaintItems();
}

} // namespace rs::ui
