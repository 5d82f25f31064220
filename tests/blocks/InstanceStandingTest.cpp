// SPDX-License-Identifier: GPL-3.0-or-later
#include "blocks/InstanceStanding.h"
#include "blocks/LibraryReader.h"
#include "blocks/ProjectInstances.h"
#include "project/ProjectFile.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

const char* kStandingLibrary = R"(rungsmith-library 1
library Test
version 1.0
block Latch
    kind macro
    version 2.0
    description en Q is set by S, reset by R.
    pin S in bit primary
    pin R in bit primary default=0
    pin Q out bit primary
    private q memory
    body S({#q}) = {S}
    body R({#q}) = {R}
    body {Q} = {#q}
)";

blocks::LibrarySet standingLibraries() {
    blocks::LibrarySet set;
    const auto read = blocks::readLibrary(kStandingLibrary);
    EXPECT_TRUE(read.ok());
    set.libraries.push_back(
        {read.library, QStringLiteral("test.rslib"), blocks::LibraryOrigin::User});
    return set;
}

// The project as reading it from a file gives it: instances expanded.
project::Project expanded(const std::string& code) {
    auto read = blocks::readProjectWithInstances(
        "! id_pluto:00=000000000000\n! pgm_pluto:00\nS0.0_0\n" + code, standingLibraries());
    EXPECT_TRUE(read.read.ok());
    return read.read.project;
}

std::vector<blocks::Standing> standings(const project::Project& project) {
    std::vector<blocks::Standing> found;
    const auto set = standingLibraries();
    for (const auto& status : blocks::instanceStatuses(project.program, 0, set))
        found.push_back(status.standing);
    return found;
}

lang::Step& onlyStep(project::Project& project) {
    return project.program.units.at(0).steps.at(0);
}

TEST(InstanceStanding, AnExpandedInstanceIsAsItsBlockMakesIt) {
    const auto project = expanded(";@block Latch S=\"I0.0\" Q=\"Q0.2\"\n;@end\n"
                                  ";@block Latch S=\"I0.1\" Q=\"Q0.3\"\n;@end\n");
    EXPECT_EQ(standings(project),
              (std::vector{blocks::Standing::AsMade, blocks::Standing::AsMade}));
    const auto set = standingLibraries(); // the statuses point into it
    const auto statuses = blocks::instanceStatuses(project.program, 0, set);
    ASSERT_NE(statuses[0].block, nullptr);
    EXPECT_EQ(statuses[0].block->name, "Latch");
    EXPECT_EQ(statuses[1].instance.record, 5U)
        << "the second record follows the first's four lines";
}

TEST(InstanceStanding, StatementsEditedByHandAreNoLongerTheBlocks) {
    auto project = expanded(";@block Latch S=\"I0.0\" Q=\"Q0.2\"\n;@end\n");
    auto& lines = onlyStep(project).lines;
    ASSERT_EQ(lines.size(), 5U);
    std::get<lang::Statement>(lines[3].body).target.address.index = 7; // Q0.2 -> Q0.7
    EXPECT_EQ(standings(project), std::vector{blocks::Standing::EditedByHand});
}

TEST(InstanceStanding, AnotherVersionOrAMissingBlockOrNoStatementsIsSaid) {
    auto project = expanded(";@block Latch S=\"I0.0\" Q=\"Q0.2\"\n;@end\n");
    auto& record = std::get<lang::CommentLine>(onlyStep(project).lines[0].body);
    const auto at = record.text.find("version=\"2.0\"");
    ASSERT_NE(at, std::string::npos) << record.text;
    record.text.replace(at, 13, "version=\"1.0\"");
    EXPECT_EQ(standings(project), std::vector{blocks::Standing::OtherVersion});

    record.text.replace(record.text.find("Latch"), 5, "Other");
    record.text.replace(record.text.find("lib=\"Test\""), 10, "lib=\"Gone\"");
    EXPECT_EQ(standings(project), std::vector{blocks::Standing::NoBlock});

    auto unexpanded = project::readProject(
        "! id_pluto:00=000000000000\n! pgm_pluto:00\nS0.0_0\n;@block Latch S=\"I0.0\" "
        "Q=\"Q0.2\"\n;@end\n");
    EXPECT_EQ(standings(unexpanded.project), std::vector{blocks::Standing::NotExpanded});
}

TEST(InstanceStanding, ACallIsCheckedAsItsExpansionWouldBe) {
    const auto project = expanded("Q0.5 = I0.4\n");
    const auto set = standingLibraries();
    const blocks::BlockDefinition& latch = *set.libraries[0].library.findBlock("Latch");
    blocks::BlockInstance call;
    call.type = "Latch";
    call.pins = {{"S", "I0.0", 0}, {"Q", "Q0.2", 0}};
    EXPECT_TRUE(blocks::callProblems(project.program, 0, latch, call).empty());

    call.pins = {{"Q", "I0.3", 0}};
    const auto problems = blocks::callProblems(project.program, 0, latch, call);
    ASSERT_EQ(lang::errorCount(problems), 2U);
    // In the block's pin order: S, then Q.
    EXPECT_NE(problems[0].message.find("input S is not bound"), std::string::npos)
        << problems[0].message;
    EXPECT_NE(problems[1].message.find("pin Q takes"), std::string::npos) << problems[1].message;
}

} // namespace
