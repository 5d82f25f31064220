// SPDX-License-Identifier: GPL-3.0-or-later
#include "ElementProblems.h"

#include "lang/Parser.h"
#include "project/UnitText.h"

namespace rs::ladder {

std::map<lang::ElementNumber, std::string> problemsByElement(const project::Project& project,
                                                             int station,
                                                             const lang::Diagnostics& diagnostics) {
    std::map<lang::ElementNumber, std::string> problems;
    if (diagnostics.empty())
        return problems;
    // Parsed again so that the syntax tree's places are those of the unit's text.
    const lang::ParseResult parsed = lang::parse(project::unitText(project, station));
    if (parsed.document.units.empty())
        return problems;
    const lang::UnitProgram& unit = parsed.document.units.front();
    for (const auto& diagnostic : diagnostics) {
        const auto element = lang::elementAt(unit, diagnostic.line, diagnostic.column);
        if (!element)
            continue;
        std::string& text = problems[*element];
        if (!text.empty())
            text += '\n';
        text += diagnostic.message;
    }
    return problems;
}

} // namespace rs::ladder
