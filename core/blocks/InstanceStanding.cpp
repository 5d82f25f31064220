// SPDX-License-Identifier: GPL-3.0-or-later
#include "InstanceStanding.h"

#include "compiler/UnitSetup.h"
#include "lang/NameResolver.h"
#include "target/UnitType.h"

namespace rs::blocks {

namespace {

// The statements and comments of an expansion, without blank lines.
std::vector<lang::Line> meaningful(std::vector<lang::Line>::const_iterator first,
                                   std::vector<lang::Line>::const_iterator last) {
    std::vector<lang::Line> lines;
    for (auto line = first; line != last; ++line)
        if (!std::holds_alternative<lang::BlankLine>(line->body))
            lines.push_back(*line);
    return lines;
}

const target::UnitTypeInfo& typeOf(const lang::Document& document, int station) {
    lang::Diagnostics ignored; // the compiler reports what is wrong with the units
    const compiler::UnitSetups setups = compiler::collectUnits(document, ignored);
    const auto found = setups.find(station);
    if (found != setups.end() && found->second.type)
        return *found->second.type;
    return target::unitTypeInfo(target::baseType(lang::UnitFamily::Pluto));
}

} // namespace

const LoadedLibrary* libraryOf(const BlockInstance& instance, const LibrarySet& libraries) {
    return instance.library.empty() ? libraries.libraryOfBlock(instance.type)
                                    : libraries.findLibrary(instance.library);
}

PrivateVariables freeVariables(const lang::Document& document, int station,
                               const std::vector<const BlockInstance*>& instances) {
    PrivateVariables variables(typeOf(document, station), lang::instructionSetOf(document, station),
                               station, usedAddresses(document, station));
    for (const BlockInstance* instance : instances)
        for (const auto& variable : instance->privates) {
            const lang::AddressWord word = lang::readAddressWord(variable.operand);
            if (word.shape == lang::AddressWord::Shape::Variable)
                variables.take(word.address);
        }
    return variables;
}

Standing standingOf(const BlockDefinition* block, const BlockInstance& instance,
                    const lang::Step& step, UnitFrame& frame, const PrivateVariables& variables) {
    if (!instance.hasExpansion())
        return Standing::NotExpanded;
    if (!block)
        return Standing::NoBlock;
    if (!instance.version.empty() && instance.version != block->version)
        return Standing::OtherVersion;
    BlockInstance again = instance;
    PrivateVariables spare = variables;
    const Expansion expected = expandInstance(*block, again, frame, spare);
    const auto first = step.lines.begin() + std::ptrdiff_t(instance.record + 1);
    const auto last = step.lines.begin() + std::ptrdiff_t(instance.end);
    return expected.ok() && meaningful(first, last) == expected.lines ? Standing::AsMade
                                                                      : Standing::EditedByHand;
}

lang::Diagnostics callProblems(const lang::Document& document, int station,
                               const BlockDefinition& block, const BlockInstance& instance) {
    std::vector<const BlockInstance*> others;
    std::vector<BlockInstance> found;
    for (const auto& unit : document.units)
        if (unit.station() == station)
            for (const auto& step : unit.steps)
                for (auto& other : findInstances(step).instances)
                    found.push_back(std::move(other));
    for (const auto& other : found)
        others.push_back(&other);
    PrivateVariables variables = freeVariables(document, station, others);
    UnitFrame frame(document, station);
    BlockInstance trial = instance;
    return expandInstance(block, trial, frame, variables).diagnostics;
}

bool drawnAsBox(const InstanceStatus& status) {
    switch (status.standing) {
    case Standing::AsMade:
    case Standing::OtherVersion:
        return true;
    case Standing::NotExpanded:
        return status.block != nullptr;
    case Standing::EditedByHand:
    case Standing::NoBlock:
        break;
    }
    return false;
}

const InstanceStatus* statusAt(const std::vector<InstanceStatus>& statuses,
                               const lang::StepAddress& step, std::size_t record) {
    for (const auto& status : statuses)
        if (status.address == step && status.instance.record == record)
            return &status;
    return nullptr;
}

std::vector<InstanceStatus> instanceStatuses(const lang::Document& document, int station,
                                             const LibrarySet& libraries) {
    std::vector<InstanceStatus> statuses;
    const lang::UnitProgram* unit = nullptr;
    for (const auto& candidate : document.units)
        if (candidate.station() == station)
            unit = &candidate;
    if (!unit)
        return statuses;
    for (std::size_t step = 0; step < unit->steps.size(); ++step)
        for (auto& instance : findInstances(unit->steps[step]).instances)
            statuses.push_back({step, unit->steps[step].address, std::move(instance),
                                Standing::NoBlock, nullptr, nullptr});
    if (statuses.empty())
        return statuses;
    std::vector<const BlockInstance*> instances;
    for (const auto& status : statuses)
        instances.push_back(&status.instance);
    const PrivateVariables variables = freeVariables(document, station, instances);
    UnitFrame frame(document, station);
    for (auto& status : statuses) {
        status.library = libraryOf(status.instance, libraries);
        status.block =
            status.library ? status.library->library.findBlock(status.instance.type) : nullptr;
        if (!status.block)
            status.library = nullptr;
        status.standing =
            standingOf(status.block, status.instance, unit->steps[status.step], frame, variables);
    }
    return statuses;
}

} // namespace rs::blocks
