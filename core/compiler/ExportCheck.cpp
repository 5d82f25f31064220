// SPDX-License-Identifier: GPL-3.0-or-later
#include "ExportCheck.h"

#include "project/ExportedVariables.h"

#include <set>

namespace rs::compiler {

namespace {

void error(lang::Diagnostics& diagnostics, const UnitSetup& unit, std::string message) {
    diagnostics.push_back(
        {lang::Severity::Error, unit.declared.line, unit.declared.column, std::move(message)});
}

} // namespace

void collectExports(const project::Project& project, UnitSetups& units,
                    lang::Diagnostics& diagnostics) {
    for (const lang::Address& address : project.exportedVariables) {
        auto unit = units.find(address.unit);
        if (unit == units.end())
            continue; // the unit is gone; saving the project drops its records
        if (auto refusal = project::checkExportable(project, address)) {
            error(diagnostics, unit->second, *refusal);
            continue;
        }
        unit->second.exported.insert(address);
    }
    std::set<lang::Address> accepted;
    for (const auto& [station, unit] : units)
        accepted.insert(unit.exported.begin(), unit.exported.end());
    int total = 0;
    for (const auto& [station, unit] : units) {
        const int pairs = project::telegramPairs(accepted, station);
        total += pairs;
        if (pairs > project::kTelegramPairsPerUnit)
            error(diagnostics, unit,
                  "unit " + std::to_string(station) + " exports variables for " +
                      std::to_string(pairs) + " extra telegram pairs; a unit may add " +
                      std::to_string(project::kTelegramPairsPerUnit));
    }
    if (total > project::kTelegramPairsPerProject)
        error(diagnostics, units.begin()->second,
              "the project's exported variables need " + std::to_string(total) +
                  " extra telegram pairs; a project may add " +
                  std::to_string(project::kTelegramPairsPerProject));
}

} // namespace rs::compiler
