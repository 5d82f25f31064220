// SPDX-License-Identifier: GPL-3.0-or-later
#include "UnitAsiOptions.h"

#include "UnitSettings.h"

namespace rs::project {

AsiOptions asiOptionsOf(const Project& project, int station) {
    auto it = project.asiOptions.find(station);
    return it == project.asiOptions.end() ? AsiOptions{} : it->second;
}

void setAsiOptions(Project& project, int station, const AsiOptions& options) {
    if (options == AsiOptions{})
        project.asiOptions.erase(station);
    else
        project.asiOptions[station] = options;
}

std::set<lang::Address> configuredAsiVariables(const Project& project, int station) {
    std::set<lang::Address> variables;
    const target::UnitTypeInfo& type = unitTypeOf(project, station);
    for (const auto& [address, slave] : asiOptionsOf(project, station).slaves)
        for (const lang::Address& variable : slaveVariables(type, station, address, slave.type))
            if (target::hasVariable(type, variable, instructionSetOf(project, station)))
                variables.insert(variable);
    return variables;
}

} // namespace rs::project
