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

std::optional<NetworkLayout> ProjectLadder::layout(const lang::StepAddress& step,
                                                   int number) const {
    const auto unit = m_units.find(step.unit);
    if (unit == m_units.end())
        return std::nullopt;
    const auto& pages = unit->second.pages;
    const auto page = std::find_if(pages.begin(), pages.end(),
                                   [&](const StepPage& p) { return p.address == step; });
    if (page == pages.end() || number < 1 ||
        number > static_cast<int>(page->ladder.networks.size()))
        return std::nullopt;
    const auto index = static_cast<std::size_t>(number - 1);
    LayoutContext context;
    context.number = number;
    context.firstStatement = page->firstStatements[index];
    context.symbols = &unit->second.symbols;
    const Network& network = page->ladder.networks[index];
    if (network.block)
        if (const blocks::InstanceStatus* status =
                blocks::statusAt(unit->second.statuses, step, network.block->instance.record))
            context.block = status->block;
    return layoutNetwork(network, context);
}

} // namespace rs::ladder
