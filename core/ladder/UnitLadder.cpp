// SPDX-License-Identifier: GPL-3.0-or-later
#include "UnitLadder.h"

#include "LadderToText.h"
#include "TextToLadder.h"

namespace rs::ladder {

std::vector<StepPage> unitLadder(const lang::UnitProgram& unit, const UnitBlockShown& shown) {
    std::vector<StepPage> pages;
    std::uint32_t statement = 0;
    for (const auto& step : unit.steps) {
        BlockShown inStep;
        if (shown)
            inStep = [&](const blocks::BlockInstance& instance) {
                return shown(step, instance);
            };
        StepPage page{step.address, toLadder(step, inStep), {}, statement};
        for (const auto& network : page.ladder.networks) {
            page.firstStatements.push_back(statement);
            statement += static_cast<std::uint32_t>(statementCount(network));
        }
        pages.push_back(std::move(page));
    }
    return pages;
}

std::size_t sequenceLines(const lang::UnitProgram& unit, int sequence) {
    std::size_t lines = 0;
    for (const auto& step : unit.steps)
        if (step.address.sequence == sequence)
            lines += step.lines.size();
    return lines;
}

bool setStepLadder(lang::UnitProgram& unit, const lang::StepAddress& address,
                   const StepLadder& ladder) {
    for (auto& step : unit.steps) {
        if (step.address == address) {
            step.lines = toLines(ladder);
            return true;
        }
    }
    return false;
}

} // namespace rs::ladder
