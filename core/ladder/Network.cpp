// SPDX-License-Identifier: GPL-3.0-or-later
#include "Network.h"

#include "project/Annotation.h"

namespace rs::ladder {

BlockCall unexpandedCall(blocks::BlockInstance instance) {
    instance.record = 0;
    instance.end = 1;
    BlockCall call;
    call.lines.push_back(
        {lang::CommentLine{blocks::recordText(instance), false}, std::nullopt, {}});
    call.lines.push_back(
        {lang::CommentLine{project::formatAnnotation({blocks::kEndRecord, {}, {}}), false},
         std::nullopt,
         {}});
    call.instance = std::move(instance);
    return call;
}

int statementCount(const Network& network) {
    int count = 0;
    if (network.block)
        for (const auto& line : network.block->lines)
            count += std::holds_alternative<lang::Statement>(line.body) ? 1 : 0;
    for (const auto& item : network.items)
        if (const auto* rung = std::get_if<Rung>(&item))
            count += static_cast<int>(rung->outputs.size());
    return count;
}

std::size_t lineCount(const Network& network) {
    std::size_t count = network.record ? 1 : 0;
    if (network.block)
        count += network.block->lines.size();
    for (const auto& item : network.items) {
        const auto* rung = std::get_if<Rung>(&item);
        count += rung ? rung->outputs.size() : 1;
    }
    return count;
}

} // namespace rs::ladder
