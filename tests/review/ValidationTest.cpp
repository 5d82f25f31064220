// SPDX-License-Identifier: GPL-3.0-or-later
#include "review/Validation.h"
#include "compiler/Compiler.h"
#include "project/ProjectFile.h"

#include "TextEdit.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

using rs::test::replaced;

const char* kProject = "$name Validated\n"
                       "! id_pluto:00=000000000000\n"
                       "! type_pluto:00=A20,is3\n"
                       "! id_pluto:01=000000000001\n"
                       "! type_pluto:01=A20,is3\n"
                       "! pgm_pluto:00\n"
                       "! I0.1=Start\n"
                       "S0.0_0\n"
                       "Q0.2 = I0.0 * Start     ; the motor\n"
                       "M0.1 = I0.2 + /I0.3\n"
                       "! pgm_pluto:01\n"
                       "S1.0_0\n"
                       "Q1.2 = I1.0 * I1.1\n";

// The text validated, as `validate` writes it.
std::string validated(const std::string& text) {
    project::ProjectReadResult read = project::readProject(text);
    EXPECT_TRUE(read.ok());
    const compiler::CompileResult compiled = compiler::compile(read.project);
    EXPECT_EQ(compiled.errors(), 0);
    read.project.baseline =
        review::validatedBaseline(read.project, compiled, "2026-12-01", "A. Reviewer", "R-17");
    return project::writeProject(read.project);
}

review::ProjectDiff sinceValidation(const std::string& text) {
    const project::ProjectReadResult read = project::readProject(text);
    EXPECT_TRUE(read.ok()) << text;
    EXPECT_TRUE(read.project.baseline.has_value());
    return review::changesSinceValidation(read.project, compiler::compile(read.project));
}

std::vector<std::string> networkLines(const review::ProjectDiff& diff) {
    std::vector<std::string> lines;
    for (const auto& network : diff.networks)
        lines.push_back(network.describe());
    return lines;
}

} // namespace

TEST(Validation, TheBaselineIsKeptInTheFileAndFormatKeepsIt) {
    const std::string text = validated(kProject);
    EXPECT_NE(text.find(";@validated date=\"2026-12-01\" by=\"A. Reviewer\" comment=\"R-17\" "
                        "signature=\""),
              std::string::npos)
        << text;
    const project::ProjectReadResult read = project::readProject(text);
    ASSERT_TRUE(read.ok());
    ASSERT_TRUE(read.project.baseline);
    EXPECT_EQ(read.project.baseline->units.size(), 2u);
    EXPECT_EQ(project::writeProject(read.project), text);
}

TEST(Validation, TheBaselineChangesNoSignature) {
    const auto before = compiler::compileText(kProject);
    const auto after = compiler::compileText(validated(kProject));
    EXPECT_EQ(after.signatures, before.signatures);
    EXPECT_EQ(after.projectSignature, before.projectSignature);
}

TEST(Validation, RightAfterValidationNothingChanged) {
    const review::ProjectDiff diff = sinceValidation(validated(kProject));
    EXPECT_FALSE(diff.behaviourChanged());
    EXPECT_TRUE(diff.networks.empty());
    EXPECT_TRUE(diff.units.empty());
    EXPECT_EQ(diff.lines(), std::vector<std::string>{"no change in behaviour"});
}

TEST(Validation, ChangesSinceAreNetworkByNetwork) {
    const std::string base = validated(kProject);
    const review::ProjectDiff added =
        sinceValidation(replaced(base, "S0.0_0\n", "S0.0_0\nM0.5 = I0.5\n"));
    EXPECT_EQ(networkLines(added), std::vector<std::string>{"Pluto 00 S0.0_0 network 1: added"});
    EXPECT_TRUE(added.behaviourChanged());
    EXPECT_EQ(added.changedStations, std::vector<int>{0});

    const review::ProjectDiff changed = sinceValidation(replaced(base, "I1.1", "I1.2"));
    EXPECT_EQ(networkLines(changed),
              std::vector<std::string>{"Pluto 01 S1.0_0 network 1: changed"});
    EXPECT_EQ(changed.changedStations, std::vector<int>{1});

    const review::ProjectDiff comment = sinceValidation(replaced(base, "the motor", "the pump"));
    EXPECT_TRUE(comment.networks.empty());
    EXPECT_FALSE(comment.behaviourChanged());
}

TEST(Validation, AMalformedRecordIsAnErrorAtItsLine) {
    const std::string text = replaced(kProject, "$name Validated\n",
                                      "$name Validated\n;@validated 00 signature=\"XYZ\"\n");
    const project::ProjectReadResult read = project::readProject(text);
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.diagnostics[0].line, 2);
    EXPECT_NE(read.diagnostics[0].message.find("8 hexadecimal digits"), std::string::npos);
}
