// SPDX-License-Identifier: GPL-3.0-or-later
#include "review/NetworkDiff.h"
#include "RandomProgram.h"
#include "lang/NameResolver.h"
#include "project/ProjectFile.h"
#include "review/EditorNetworks.h"
#include "review/NetworkMeaning.h"

#include "TextEdit.h"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <tuple>

using namespace rs;
using review::NetworkDifference;
using review::Pairing;

namespace {

using rs::test::replaced;

project::Project randomProject(unsigned seed) {
    project::Project project;
    project.program = test::RandomProgram(seed).document();
    lang::resolveNames(project.program); // names it cannot resolve stay names
    return project;
}

project::Project networkProject(const std::string& text) {
    project::ProjectReadResult result = project::readProject(text);
    EXPECT_TRUE(result.ok());
    return std::move(result.project);
}

std::vector<std::string> described(const std::vector<NetworkDifference>& differences) {
    std::vector<std::string> lines;
    for (const auto& difference : differences)
        lines.push_back(difference.describe());
    return lines;
}

// The statement lines of a step, by their index among its lines.
std::vector<std::size_t> statementLines(const lang::Step& step) {
    std::vector<std::size_t> lines;
    for (std::size_t i = 0; i < step.lines.size(); ++i)
        if (std::holds_alternative<lang::Statement>(step.lines[i].body))
            lines.push_back(i);
    return lines;
}

const char* kPress = "$name Press\n"
                     "! id_pluto:00=000000000000\n"
                     "! type_pluto:00=A20,is3\n"
                     "! pgm_pluto:00\n"
                     "! I0.1=Start\n"
                     "S0.0_0\n"
                     "Q0.2 = I0.0 * Start     ; the motor\n"
                     "M0.1 = I0.2 + /I0.3\n"
                     "M0.2 = TON(2s10) * I0.4\n"
                     "S0.1_0\n"
                     "J(1) = I0.5\n"
                     "S0.1_1\n"
                     "Q0.3 = I0.6\n";

} // namespace

TEST(NetworkDiff, ARandomProgramDiffedWithItselfIsEmpty) {
    for (unsigned seed = 1; seed <= 300; ++seed) {
        const project::Project project = randomProject(seed);
        EXPECT_TRUE(review::networkDifferences(project, project).empty()) << seed;
        // Printed and read back (the canonical text): still nothing.
        const project::ProjectReadResult reread =
            project::readProject(project::writeProject(project));
        if (reread.ok()) {
            EXPECT_TRUE(review::networkDifferences(project, reread.project).empty()) << seed;
        }
    }
}

TEST(NetworkDiff, OneInsertedStatementIsOneAddedNetworkOfItsStep) {
    int tried = 0;
    for (unsigned seed = 1; seed <= 300; ++seed) {
        const project::Project before = randomProject(seed);
        if (before.program.units.empty() || before.program.units[0].steps.empty())
            continue;
        project::Project after = before;
        lang::Step& step = after.program.units[0].steps[0];
        std::mt19937 random(seed);
        const std::size_t at =
            std::uniform_int_distribution<std::size_t>(0, step.lines.size())(random);
        step.lines.insert(step.lines.begin() + static_cast<std::ptrdiff_t>(at),
                          lang::Line{test::RandomProgram(seed + 1000).statement(), {}, {}});
        // In a step whose networks are grouped, the statement joins a network.
        const auto differences = review::networkDifferences(before, after);
        ASSERT_EQ(differences.size(), 1u) << seed;
        EXPECT_TRUE(differences[0].change == Pairing::Added ||
                    differences[0].change == Pairing::Changed)
            << seed;
        EXPECT_EQ(differences[0].step, step.address);
        EXPECT_EQ(differences[0].station, after.program.units[0].station());
        ++tried;
    }
    EXPECT_GT(tried, 50);
}

TEST(NetworkDiff, OneReplacedStatementIsOneChangedNetwork) {
    int tried = 0;
    for (unsigned seed = 1; seed <= 300; ++seed) {
        const project::Project before = randomProject(seed);
        if (before.program.units.empty() || before.program.units[0].steps.empty())
            continue;
        const lang::Step& oldStep = before.program.units[0].steps[0];
        const auto statements = statementLines(oldStep);
        if (statements.empty())
            continue;
        project::Project after = before;
        lang::Step& step = after.program.units[0].steps[0];
        const std::size_t line = statements[seed % statements.size()];
        lang::Statement replacement = test::RandomProgram(seed + 2000).statement();
        const lang::Line replacementLine{replacement, {}, {}};
        const int station = after.program.units[0].station();
        if (review::networkMeaning(after.program, station, {{}, {&replacementLine}}) ==
            review::networkMeaning(before.program, station, {{}, {&oldStep.lines[line]}}))
            continue; // the same statement, or another spelling of it
        step.lines[line].body = replacement;
        const auto differences = review::networkDifferences(before, after);
        ASSERT_EQ(differences.size(), 1u) << seed;
        EXPECT_EQ(differences[0].change, Pairing::Changed) << seed;
        EXPECT_EQ(differences[0].step, step.address);
        ++tried;
    }
    EXPECT_GT(tried, 50);
}

TEST(NetworkDiff, EachChangeIsReportedOnceOnItsSide) {
    // Random pairs of programs: a network appears at most once per side.
    for (unsigned seed = 1; seed <= 200; ++seed) {
        const project::Project before = randomProject(seed);
        const project::Project after = randomProject(seed + 5000);
        std::set<std::tuple<int, int, int, int, bool>> seen;
        for (const auto& d : review::networkDifferences(before, after)) {
            const bool oldSide = d.change == Pairing::Removed;
            EXPECT_TRUE(
                seen.insert({d.station, d.step.sequence, d.step.step, d.number, oldSide}).second)
                << seed << ' ' << d.describe();
            EXPECT_GE(d.number, 1);
        }
    }
}

TEST(NetworkDiff, TheLinesOfTheContract) {
    const auto before = networkProject(kPress);
    EXPECT_EQ(described(review::networkDifferences(
                  before, networkProject(replaced(kPress, "M0.1 = I0.2 + /I0.3\n",
                                                  "M0.1 = I0.2 + /I0.3\nM0.7 = I0.7\n")))),
              std::vector<std::string>{"Pluto 00 S0.0_0 network 3: added"});
    EXPECT_EQ(described(review::networkDifferences(
                  before, networkProject(replaced(kPress, "M0.1 = I0.2 + /I0.3\n", "")))),
              std::vector<std::string>{"Pluto 00 S0.0_0 network 2: removed"});
    EXPECT_EQ(described(review::networkDifferences(
                  before, networkProject(replaced(kPress, "I0.6", "I0.7")))),
              std::vector<std::string>{"Pluto 00 S0.1_1 network 1: changed"});
}

TEST(NetworkDiff, CommentsLayoutNamesAndTimerSpellingsAreNoChange) {
    const auto before = networkProject(kPress);
    for (const std::string& text :
         {replaced(kPress, "; the motor", "; the conveyor"),
          replaced(kPress, "M0.1 = I0.2 + /I0.3", "  m0.1=I0.2+/i0.3   ; now commented"),
          replaced(replaced(kPress, "! I0.1=Start", "! I0.1=Go"), "* Start", "* Go"),
          replaced(kPress, "* Start", "* I0.1"), replaced(kPress, "TON(2s10)", "T(2s10)"),
          replaced(kPress, "S0.0_0\n", "S0.0_0\n; a new comment\n\n")})
        EXPECT_TRUE(review::networkDifferences(before, networkProject(text)).empty()) << text;
}

TEST(NetworkDiff, ABlockInstanceIsOneNetworkAsTheEditorDrawsIt) {
    const std::string text = "$name Blocks\n"
                             "! id_pluto:00=000000000000\n"
                             "! type_pluto:00=A20,is3\n"
                             "! pgm_pluto:00\n"
                             "S0.0_0\n"
                             "Q0.2 = I0.0\n"
                             ";@block Latch In=\"I0.1\" Out=\"M0.1\" lib=\"Mine\" version=\"1.0\"\n"
                             "M0.1 = I0.1 + M0.1\n"
                             "M0.2 = M0.1\n"
                             ";@end\n"
                             "Q0.3 = I0.4\n";
    const auto before = networkProject(text);
    EXPECT_EQ(review::editorNetworks(before.program.units[0].steps[0]).size(), 3u);
    EXPECT_EQ(described(review::networkDifferences(
                  before, networkProject(replaced(text, "M0.2 = M0.1", "M0.2 = /M0.1")))),
              std::vector<std::string>{"Pluto 00 S0.0_0 network 2: changed"});
    EXPECT_EQ(described(review::networkDifferences(before,
                                                   networkProject(replaced(text, "I0.4", "I0.5")))),
              std::vector<std::string>{"Pluto 00 S0.0_0 network 3: changed"});
}
