// SPDX-License-Identifier: GPL-3.0-or-later
#include "UnitResources.h"

#include "BlockInstance.h"
#include "InstanceVariables.h"
#include "LibraryLimits.h"
#include "project/UnitSettings.h"
#include "project/VariableTable.h"
#include "target/UnitType.h"

#include <set>
#include <variant>

namespace rs::blocks {

namespace {

int timersIn(const lang::Expr& expr) {
    int timers = expr.kind == lang::ExprKind::Timer ? 1 : 0;
    for (const auto& child : expr.children)
        timers += timersIn(child);
    return timers;
}

int timersIn(const lang::Line& line) {
    const auto* statement = std::get_if<lang::Statement>(&line.body);
    return statement && statement->condition ? timersIn(*statement->condition) : 0;
}

// Adds the memory or the register words an address takes.
void take(const lang::Address& address, std::set<int>& memories, std::set<int>& registers) {
    switch (address.kind) {
    case lang::AddressKind::Memory:
        memories.insert(address.index);
        break;
    case lang::AddressKind::Register:
        registers.insert(address.index);
        break;
    case lang::AddressKind::DoubleRegister:
        registers.insert(address.index);
        registers.insert(address.index + 1);
        break;
    default:
        break;
    }
}

} // namespace

UnitResources unitResources(const project::Project& project, int station) {
    UnitResources resources;
    const target::UnitTypeInfo& type = project::unitTypeOf(project, station);
    resources.timers.limit = kMaxTimers;
    resources.memories.limit =
        target::memoryCount(type, project::instructionSetOf(project, station));
    resources.registers.limit = type.registers;

    for (const auto& unit : project.program.units) {
        if (unit.station() != station)
            continue;
        for (const auto& step : unit.steps) {
            for (const auto& line : step.lines)
                resources.timers.used += timersIn(line);
            for (const auto& instance : findInstances(step).instances)
                for (std::size_t i = instance.record + 1; i < instance.end; ++i)
                    resources.timers.byBlocks += timersIn(step.lines[i]);
        }
    }

    std::set<int> memories;
    std::set<int> registers;
    for (const auto& address : project::usedVariables(project, station))
        take(address, memories, registers);
    std::set<int> privateMemories;
    std::set<int> privateRegisters;
    for (const auto& variable : instanceVariables(project, station)) {
        take(variable.address, memories, registers);
        if (variable.role == InstanceVariable::Role::Private)
            take(variable.address, privateMemories, privateRegisters);
    }
    resources.memories.used = static_cast<int>(memories.size());
    resources.memories.byBlocks = static_cast<int>(privateMemories.size());
    resources.registers.used = static_cast<int>(registers.size());
    resources.registers.byBlocks = static_cast<int>(privateRegisters.size());
    return resources;
}

} // namespace rs::blocks
