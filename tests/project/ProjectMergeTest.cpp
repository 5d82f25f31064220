// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/ProjectMerge.h"
#include "project/ProjectFile.h"
#include "project/UnitText.h"

#include <gtest/gtest.h>

#include <string>

using namespace rs;

namespace {

project::Project read(const std::string& text) {
    project::ProjectReadResult read = project::readProject(text);
    EXPECT_TRUE(read.ok()) << (read.diagnostics.empty() ? "" : read.diagnostics.front().message);
    return read.project;
}

// The manual's example (Part 1, 12.2): I0.0 and I1.0 are both "Input_zero".
const std::string kFirst = "$name Line\n"
                           ";@project description=\"the first cell\"\n"
                           "! id_pluto:00=000000000000\n"
                           "! type_pluto:00=A20,is3\n"
                           "! id_pluto:02=000000000002\n"
                           "! type_pluto:02=A20,is3\n"
                           "! I0.0=Input_zero\n"
                           "! Q0.2=Lamp\n"
                           "! pgm_pluto:00\n"
                           "S0.0_0\n"
                           "Lamp = Input_zero\n"
                           "! pgm_pluto:02\n"
                           "S2.0_0\n"
                           "Q2.2 = Input_zero\n";

const std::string kSecond = "$name Cell\n"
                            "! id_pluto:01=000000000001\n"
                            ";@unit 01 description=\"the second cell\"\n"
                            ";@var R1.0 description=\"Parts\"\n"
                            "! type_pluto:01=A20,is3\n"
                            "! I1.0=Input_zero\n"
                            "! pgm_pluto:01\n"
                            "! Q1.2=Horn\n"
                            "S1.0_0\n"
                            "Horn = Input_zero\n";

TEST(ProjectMerge, UnitsOfBothWithEveryNameAndDescription) {
    const project::Project first = read(kFirst);
    std::string second = kSecond;
    second.replace(second.find("! I1.0=Input_zero"), 17, "! I1.0=Input_one");
    second.replace(second.find("Horn = Input_zero"), 17, "Horn = Input_one");
    const project::MergeResult result = project::mergeProjects(first, read(second), false);
    ASSERT_TRUE(result.merged.has_value());
    EXPECT_TRUE(result.conflicts.empty());
    const std::string text = project::writeProject(*result.merged);
    const project::Project merged = read(text);
    EXPECT_EQ(merged.stations(), (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(merged.name(), "Line");
    EXPECT_EQ(merged.description, "the first cell");
    EXPECT_EQ(merged.unitDescriptions.at(1), "the second cell");
    EXPECT_EQ(merged.variableDescriptions.at({lang::AddressKind::Register, 1, 0}), "Parts");
    EXPECT_NE(project::unitText(merged, 1).find("Horn = Input_one"), std::string::npos) << text;
    EXPECT_NE(project::unitText(merged, 0).find("Lamp = Input_zero"), std::string::npos) << text;
}

TEST(ProjectMerge, AStationInBothIsAConflictEvenIgnoringConflicts) {
    const project::MergeResult result = project::mergeProjects(read(kFirst), read(kFirst), true);
    EXPECT_FALSE(result.merged.has_value());
    ASSERT_GE(result.conflicts.size(), 2u);
    EXPECT_EQ(result.conflicts[0], "station 0 is in both projects");
    EXPECT_EQ(result.conflicts[1], "station 2 is in both projects");
}

TEST(ProjectMerge, ANameInBothIsAConflict) {
    const project::MergeResult result = project::mergeProjects(read(kFirst), read(kSecond), false);
    EXPECT_FALSE(result.merged.has_value());
    EXPECT_EQ(result.conflicts,
              std::vector<std::string>{"the name 'Input_zero' is in both projects (I0.0, I1.0)"});
}

// Ignoring conflicts, each unit's code means its own variable by the shared
// name, as the manual says; a third unit that read it sees the address.
TEST(ProjectMerge, IgnoringConflictsAnameStaysOnlyInTheUnitsThatDefineIt) {
    const project::MergeResult result = project::mergeProjects(read(kFirst), read(kSecond), true);
    ASSERT_TRUE(result.merged.has_value());
    EXPECT_EQ(result.conflicts.size(), 1u); // still said
    const std::string text = project::writeProject(*result.merged);
    const project::Project merged = read(text);
    const std::string zero = project::unitText(merged, 0);
    const std::string one = project::unitText(merged, 1);
    const std::string two = project::unitText(merged, 2);
    EXPECT_NE(zero.find("I0.0=Input_zero"), std::string::npos) << text;
    EXPECT_NE(zero.find("Lamp = Input_zero"), std::string::npos) << text;
    EXPECT_NE(one.find("I1.0=Input_zero"), std::string::npos) << text;
    EXPECT_NE(one.find("Horn = Input_zero"), std::string::npos) << text;
    EXPECT_NE(two.find("Q2.2 = I0.0"), std::string::npos) << text;
    EXPECT_EQ(two.find("Input_zero"), std::string::npos) << text;
}

} // namespace
