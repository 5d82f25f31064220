// SPDX-License-Identifier: GPL-3.0-or-later
#include "EditorNetworks.h"

#include "blocks/BlockInstance.h"
#include "project/Annotation.h"

namespace rs::review {

// Follows ladder::toLadder, which draws every well-formed instance as a box
// unless the editor is told otherwise; the review numbers them all as boxes.
std::vector<project::Network> editorNetworks(const lang::Step& step) {
    const std::vector<blocks::BlockInstance> instances = blocks::findInstances(step).instances;
    auto nextInstance = instances.begin();
    std::vector<project::Network> networks;
    bool grouping = false;
    for (std::size_t index = 0; index < step.lines.size(); ++index) {
        if (nextInstance != instances.end() && nextInstance->record == index) {
            project::Network block;
            for (std::size_t line = index; line <= nextInstance->end; ++line)
                block.lines.push_back(&step.lines[line]);
            networks.push_back(std::move(block));
            index = nextInstance->end;
            ++nextInstance;
            grouping = false; // what follows is not part of the block
            continue;
        }
        const lang::Line& line = step.lines[index];
        if (const auto annotation = project::annotationOn(line);
            annotation && annotation->kind == "network") {
            networks.push_back({annotation->value("comment"), {}});
            grouping = true;
            continue;
        }
        const bool statement = std::holds_alternative<lang::Statement>(line.body);
        if (statement && !grouping)
            networks.push_back({});
        if (!networks.empty())
            networks.back().lines.push_back(&line);
    }
    return networks;
}

} // namespace rs::review
