// SPDX-License-Identifier: GPL-3.0-or-later
#include "ImageSetup.h"

#include <algorithm>

namespace rs::compiler {

namespace {

void addTerminals(UnitImage& image, TerminalSetup::Group group,
                  const std::map<int, TerminalDeclaration>& declarations) {
    for (const auto& [number, declaration] : declarations) {
        TerminalSetup terminal{group, declaration.kind, static_cast<std::uint16_t>(number),
                               declaration.options};
        std::sort(terminal.options.begin(), terminal.options.end());
        image.terminals.push_back(std::move(terminal));
    }
}

} // namespace

void addSetup(UnitImage& image, const UnitSetup& unit, const project::Project& project) {
    addTerminals(image, TerminalSetup::Terminal, unit.terminals);
    addTerminals(image, TerminalSetup::SafetyOutput, unit.safetyOutputs);
    addTerminals(image, TerminalSetup::Analogue, unit.analogTerminals);
    image.exported.assign(unit.exported.begin(), unit.exported.end());
    for (const auto& address : project.remanentVariables)
        if (address.unit == unit.station)
            image.remanent.push_back(address);
}

} // namespace rs::compiler
