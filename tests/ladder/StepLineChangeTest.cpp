// SPDX-License-Identifier: GPL-3.0-or-later
#include "ladder/StepLineChange.h"
#include "RandomCondition.h"
#include "RandomNetworks.h"
#include "RandomProgram.h"
#include "blocks/BlockInstance.h"
#include "ladder/TextToLadder.h"
#include "project/Annotation.h"

#include <gtest/gtest.h>

namespace {

using namespace rs::ladder;

StepPage pageOf(const rs::lang::Step& step, std::uint32_t firstStatement) {
    StepPage page{step.address, toLadder(step), {}, firstStatement};
    for (const auto& network : page.ladder.networks) {
        page.firstStatements.push_back(firstStatement);
        firstStatement += static_cast<std::uint32_t>(statementCount(network));
    }
    return page;
}

rs::lang::Line networkRecord(const std::string& comment) {
    return {rs::lang::CommentLine{
                rs::project::formatAnnotation({"network", {}, {{"comment", comment}}}), false},
            std::nullopt,
            {}};
}

// Random steps (statements, comment and blank lines, network records, rungs
// with several outputs) get random runs of lines replaced; the page brought
// up to date from the run is the page read from the whole step anew, and
// only the networks near the run were read again.
TEST(StepLineChange, APageFollowingARunOfLinesIsThePageReadAnew) {
    int edits = 0;
    std::size_t reread = 0;
    for (unsigned seed = 1; seed <= 300; ++seed) {
        rs::test::RandomProgram program(seed);
        rs::test::RandomCondition random(seed);
        rs::lang::Document document = program.document();
        std::vector<rs::lang::Line> donor;
        for (auto& unit : document.units)
            for (auto& step : unit.steps) {
                rs::test::addNetworkStructure(step, random);
                donor.insert(donor.end(), step.lines.begin(), step.lines.end());
            }
        for (const auto& unit : document.units)
            for (const auto& original : unit.steps) {
                rs::lang::Step step = original;
                StepPage page = pageOf(step, 17);
                for (int round = 0; round < 6; ++round) {
                    const auto size = static_cast<int>(step.lines.size());
                    const auto first = static_cast<std::size_t>(random.uniform(0, size));
                    const auto removed = static_cast<std::size_t>(
                        random.uniform(0, std::min(6, size - static_cast<int>(first))));
                    std::vector<rs::lang::Line> added;
                    const int count = random.uniform(0, 6);
                    for (int i = 0; i < count && !donor.empty(); ++i)
                        added.push_back(random.chance(15)
                                            ? networkRecord(i % 2 ? "Added" : "")
                                            : donor[static_cast<std::size_t>(random.uniform(
                                                  0, static_cast<int>(donor.size()) - 1))]);
                    const auto at = step.lines.begin() + static_cast<std::ptrdiff_t>(first);
                    const std::vector<rs::lang::Line> old(
                        at, at + static_cast<std::ptrdiff_t>(removed));
                    step.lines.insert(
                        step.lines.erase(at, at + static_cast<std::ptrdiff_t>(removed)),
                        added.begin(), added.end());

                    const StepPage before = page;
                    const auto change = followLineChange(page, step, first, old, added.size());
                    ASSERT_TRUE(change) << "seed " << seed;
                    const StepPage fresh = pageOf(step, 17);
                    ASSERT_EQ(page.ladder, fresh.ladder) << "seed " << seed << " round " << round;
                    ASSERT_EQ(page.firstStatements, fresh.firstStatements) << "seed " << seed;
                    // What the change says was kept is what was there.
                    ASSERT_EQ(before.ladder.networks.size() - change->removed + change->added,
                              page.ladder.networks.size());
                    for (std::size_t n = 0; n < change->first; ++n)
                        ASSERT_EQ(before.ladder.networks[n], page.ladder.networks[n]);
                    for (std::size_t n = change->first + change->removed;
                         n < before.ladder.networks.size(); ++n)
                        ASSERT_EQ(before.ladder.networks[n],
                                  page.ladder.networks[n - change->removed + change->added]);
                    std::int64_t statements = 0;
                    for (const auto& network : page.ladder.networks)
                        statements += statementCount(network);
                    for (const auto& network : before.ladder.networks)
                        statements -= statementCount(network);
                    ASSERT_EQ(change->statementShift, statements);
                    ++edits;
                    reread += change->removed;
                }
            }
    }
    EXPECT_GT(edits, 1000);
    // A run of up to six lines touches two or three networks, not the step.
    EXPECT_LT(static_cast<double>(reread) / edits, 3.0);
}

TEST(StepLineChange, ARunWithABlockRecordIsLeftToTheWholeUnit) {
    rs::lang::Step step{{0, 0, 0}, std::nullopt, {}, {networkRecord("A"), networkRecord("B")}};
    StepPage page = pageOf(step, 0);
    const StepPage before = page;
    const rs::lang::Line record{
        rs::lang::CommentLine{rs::project::formatAnnotation({rs::blocks::kEndRecord, {}, {}}),
                              false},
        std::nullopt,
        {}};
    step.lines.insert(step.lines.begin() + 1, record);
    EXPECT_FALSE(followLineChange(page, step, 1, {}, 1));
    EXPECT_EQ(page.ladder, before.ladder);
}

} // namespace
