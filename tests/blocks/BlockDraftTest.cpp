// SPDX-License-Identifier: GPL-3.0-or-later
#include "blocks/BlockDraft.h"
#include "blocks/InstanceStanding.h"
#include "blocks/LibraryReader.h"
#include "blocks/LibraryWriter.h"
#include "blocks/ProjectInstances.h"
#include "lang/Printer.h"
#include "project/ProjectFile.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

const std::string kDraftHead = "! id_pluto:00=000000000000\n"
                               "! type_pluto:00=A20,is3\n"
                               "! I0.12=EStop\n"
                               "! pgm_pluto:00\n"
                               "S0.0_0\n";

// The first two statements latch M0.5, which nothing else uses, and light a
// lamp after a delay; the third uses M0.6, so M0.6 stays a pin.
const std::string kCode = "M0.5 = EStop * (I0.3 + M0.5)   ; latched\n"
                          "Q0.17 = M0.5 * M0.6 * TON(R0.2)\n"
                          "Q0.4 = M0.6\n";

struct Split {
    project::Project project;
    std::vector<lang::Line> chosen;
    std::vector<lang::Line> rest;
};

Split split(const std::string& code, std::size_t chosen) {
    auto read = project::readProject(kDraftHead + code);
    EXPECT_TRUE(read.ok());
    Split result{read.project, {}, {}};
    const auto& lines = read.project.program.units.at(0).steps.at(0).lines;
    result.chosen.assign(lines.begin(), lines.begin() + std::ptrdiff_t(chosen));
    result.rest.assign(lines.begin() + std::ptrdiff_t(chosen), lines.end());
    return result;
}

std::vector<std::string> printed(const std::vector<lang::Line>& lines) {
    std::vector<std::string> statements;
    for (const auto& line : lines)
        if (const auto* statement = std::get_if<lang::Statement>(&line.body))
            statements.push_back(lang::printStatement(*statement));
    return statements;
}

TEST(BlockDraft, ReadsBecomeInputsWritesOutputsAndAMemoryOnlyTheyUsePrivate) {
    const Split s = split(kCode, 2);
    const auto draft = blocks::draftBlock("LatchLamp", s.chosen, blocks::addressesIn(s.rest));
    ASSERT_TRUE(draft.refusal.empty()) << draft.refusal;
    std::vector<std::string> pins;
    for (const auto& pin : draft.block.pins)
        pins.push_back(pin.name + (pin.direction == blocks::PinDirection::In ? " in " : " out ") +
                       std::to_string(static_cast<int>(pin.kind)));
    EXPECT_EQ(pins, (std::vector<std::string>{"EStop in 0", "I0_3 in 0", "M0_6 in 0", "R0_2 in 3",
                                              "Q0_17 out 0"}));
    ASSERT_EQ(draft.block.privates.size(), 1U);
    EXPECT_EQ(draft.block.privates[0].name, "M0_5");
    EXPECT_EQ(draft.block.timers, 1);
    EXPECT_EQ(draft.block.body,
              (std::vector<std::string>{"{#M0_5} = {EStop} * ({I0_3} + {#M0_5})",
                                        "{Q0_17} = {#M0_5} * {M0_6} * TON({R0_2})"}));
    EXPECT_EQ(blocks::recordText(draft.instance),
              "@block LatchLamp EStop=\"EStop\" I0_3=\"I0.3\" M0_6=\"M0.6\" R0_2=\"R0.2\" "
              "Q0_17=\"Q0.17\" #M0_5=\"M0.5\"");
}

TEST(BlockDraft, TheBlockReadsBackAndItsInstanceExpandsToTheSameStatements) {
    const Split s = split(kCode, 2);
    auto draft = blocks::draftBlock("LatchLamp", s.chosen, blocks::addressesIn(s.rest),
                                    {{lang::readAddressWord("Q0.17").address, "Lamp"}});
    ASSERT_TRUE(draft.refusal.empty()) << draft.refusal;
    draft.block.version = "1.0";
    draft.block.description.english = "Made from two networks.";
    blocks::BlockLibrary library{"Mine", "1.0", {"Blocks of the test.", {}, {}}, {draft.block}};
    const std::string text = blocks::writeLibrary(library);
    const auto read = blocks::readLibrary(text);
    ASSERT_TRUE(read.ok()) << text << (read.diagnostics.empty() ? "" : read.diagnostics[0].message);
    EXPECT_EQ(read.library, library);

    blocks::LibrarySet set;
    set.libraries.push_back(
        {read.library, QStringLiteral("mine.rslib"), blocks::LibraryOrigin::User});
    draft.instance.library = "Mine";
    const std::string project =
        kDraftHead + ";" + blocks::recordText(draft.instance) + "\n;@end\nQ0.4 = M0.6\n";
    const auto expanded = blocks::readProjectWithInstances(project, set);
    ASSERT_TRUE(expanded.read.ok());
    EXPECT_TRUE(expanded.expanded);
    const auto& lines = expanded.read.project.program.units.at(0).steps.at(0).lines;
    EXPECT_EQ(printed(lines), printed(project::readProject(kDraftHead + kCode)
                                          .project.program.units.at(0)
                                          .steps.at(0)
                                          .lines));
    const auto statuses = blocks::instanceStatuses(expanded.read.project.program, 0, set);
    ASSERT_EQ(statuses.size(), 1U);
    EXPECT_EQ(statuses[0].standing, blocks::Standing::AsMade);
}

TEST(BlockDraft, JumpsBadNamesAndNothingAreRefused) {
    const Split jumping = split("J(+1) = I0.1\n", 1);
    EXPECT_FALSE(blocks::draftBlock("Jumps", jumping.chosen, {}).refusal.empty());
    const Split s = split(kCode, 2);
    EXPECT_FALSE(blocks::draftBlock("2Fast", s.chosen, {}).refusal.empty());
    EXPECT_FALSE(blocks::draftBlock("Ok", {}, {}).refusal.empty());
    const auto clash = blocks::draftBlock("Ok", s.chosen, {},
                                          {{lang::readAddressWord("I0.3").address, "bad name"}});
    EXPECT_NE(clash.refusal.find("'bad name'"), std::string::npos) << clash.refusal;
}

TEST(BlockDraft, AMemoryUsedElsewhereOrRemanentStaysAPin) {
    const Split s = split("M0.100 = I0.1\nM0.5 = I0.2\n", 2);
    const auto draft =
        blocks::draftBlock("Keep", s.chosen, {lang::readAddressWord("M0.5").address});
    ASSERT_TRUE(draft.refusal.empty()) << draft.refusal;
    EXPECT_TRUE(draft.block.privates.empty());
    ASSERT_EQ(draft.block.pins.size(), 4U);
    EXPECT_EQ(draft.block.pins[2].name, "M0_100");
    EXPECT_EQ(draft.block.pins[2].direction, blocks::PinDirection::Out);
}

} // namespace
