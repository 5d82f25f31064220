// SPDX-License-Identifier: GPL-3.0-or-later
#include "ImageSetup.h"

#include "project/CanBusCycle.h"
#include "project/UnitAsiOptions.h"

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

AsiSetup asiSetup(const project::AsiOptions& options) {
    using project::AsiMode;
    AsiSetup setup;
    setup.mode = static_cast<std::uint8_t>(options.mode);
    setup.optimisation = static_cast<std::uint8_t>(options.optimisation);
    if (options.mode == AsiMode::MonitorSlave || options.mode == AsiMode::MonitorSlaveExtra)
        setup.slaveAddress = static_cast<std::uint8_t>(options.slaveAddress);
    const auto& models = project::asiSafeInputModels();
    for (const auto& [address, slave] : options.slaves) {
        AsiSlaveSetup s;
        s.number = static_cast<std::uint8_t>(address.number);
        s.b = address.b;
        s.type = static_cast<std::uint8_t>(slave.type);
        s.model = static_cast<std::uint8_t>(std::find(models.begin(), models.end(), slave.model) -
                                            models.begin());
        s.parameter = static_cast<std::uint8_t>(slave.parameter);
        s.profile[0] = static_cast<std::uint8_t>(slave.profile.io);
        s.profile[1] = static_cast<std::uint8_t>(slave.profile.id);
        s.profile[2] = static_cast<std::uint8_t>(slave.profile.id2);
        s.profile[3] = static_cast<std::uint8_t>(slave.profile.id1);
        s.monitoring = static_cast<std::uint8_t>(slave.monitoring);
        s.timeLimitMs = static_cast<std::uint32_t>(slave.timeLimitMs);
        setup.slaves.push_back(s);
    }
    return setup;
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
    image.canCycleMs = static_cast<std::uint16_t>(project::canCycleOf(project, unit.station));
    if (auto comm = project.externalComm.find(unit.station); comm != project.externalComm.end())
        for (const auto& [number, block] : comm->second)
            image.externalComm.push_back({static_cast<std::uint8_t>(number),
                                          static_cast<std::uint8_t>(block.gateway),
                                          static_cast<std::uint8_t>(block.packet),
                                          static_cast<std::uint16_t>(block.timeoutMs)});
    if (unit.type && unit.type->asiSlaves)
        image.asi = asiSetup(project::asiOptionsOf(project, unit.station));
}

} // namespace rs::compiler
