// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectLadder.h"

#include <algorithm>

namespace rs::ladder {

ProjectLadder::ProjectLadder(const project::Project& project, const blocks::LibraryPlaces& places)
    : m_libraries(blocks::librariesFor(places, project.libraries)) {
    const lang::Document& document = project.program;
    for (const auto& program : document.units) {
        const int station = program.station();
        Unit unit{{},
                  SymbolTable::of(document, station),
                  blocks::instanceStatuses(document, station, m_libraries)};
        unit.pages =
            unitLadder(program, [&](const lang::Step& step, const blocks::BlockInstance& instance) {
                const blocks::InstanceStatus* status =
                    blocks::statusAt(unit.statuses, step.address, instance.record);
                return status && blocks::drawnAsBox(*status);
            });
        m_units.insert_or_assign(station, std::move(unit));
    }
}

const StepPage* ProjectLadder::page(const lang::StepAddress& step) const {
    const auto unit = m_units.find(step.unit);
    if (unit == m_units.end())
        return nullptr;
    const auto& pages = unit->second.pages;
    const auto found = std::find_if(pages.begin(), pages.end(),
                                    [&](const StepPage& p) { return p.address == step; });
    return found == pages.end() ? nullptr : &*found;
}

int ProjectLadder::networkCount(const lang::StepAddress& step) const {
    const StepPage* found = page(step);
    return found ? static_cast<int>(found->ladder.networks.size()) : -1;
}

std::optional<NetworkLayout> ProjectLadder::layout(const lang::StepAddress& step,
                                                   int number) const {
    const StepPage* found = page(step);
    if (!found || number < 1 || number > static_cast<int>(found->ladder.networks.size()))
        return std::nullopt;
    const Unit& unit = m_units.at(step.unit);
    const auto index = static_cast<std::size_t>(number - 1);
    LayoutContext context;
    context.number = number;
    context.firstStatement = found->firstStatements[index];
    context.symbols = &unit.symbols;
    const Network& network = found->ladder.networks[index];
    if (network.block)
        if (const blocks::InstanceStatus* status =
                blocks::statusAt(unit.statuses, step, network.block->instance.record))
            context.block = status->block;
    return layoutNetwork(network, context);
}

} // namespace rs::ladder
