// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/ProjectFile.h"
#include "project/ProjectMerge.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

constexpr std::string_view kProject = "$name Line\n"
                                      ";@gateway 3 type=\"GATE-P1\"\n"
                                      ";@gateway 0 type=\"gate-e1\"\n"
                                      "! id_pluto:00=000000000000\n"
                                      "! pgm_pluto:00\n"
                                      "S0.0_0\n";

std::string firstError(std::string_view record) {
    std::string text = "$name Line\n" + std::string(record) + "\n! id_pluto:00=000000000000\n";
    for (const auto& d : project::readProject(text).diagnostics)
        if (d.severity == lang::Severity::Error)
            return std::to_string(d.line) + ":" + std::to_string(d.column) + ": " + d.message;
    return "no error";
}

} // namespace

TEST(GatewayRecords, ReadInAnyOrderWrittenByNodeAfterTheProjectRecords) {
    const auto read = project::readProject(kProject);
    ASSERT_TRUE(read.diagnostics.empty());
    ASSERT_EQ(read.project.gateways.size(), 2u);
    EXPECT_EQ(read.project.gateways.at(0).type, project::GatewayType::E1);
    EXPECT_EQ(read.project.gateways.at(3).type, project::GatewayType::P1);
    const std::string text = project::writeProject(read.project);
    EXPECT_EQ(text.substr(0, text.find("! id_pluto")),
              "$name Line\n;@gateway 0 type=\"GATE-E1\"\n;@gateway 3 type=\"GATE-P1\"\n");
    EXPECT_EQ(project::writeProject(project::readProject(text).project), text);
}

TEST(GatewayRecords, AMalformedRecordIsAnErrorAtItsLine) {
    EXPECT_EQ(firstError(";@gateway 16 type=\"GATE-E1\""),
              "2:1: @gateway needs a node address 0-15, as in ;@gateway 0 type=\"GATE-E1\"");
    EXPECT_EQ(firstError(";@gateway type=\"GATE-E1\""),
              "2:1: @gateway needs a node address 0-15, as in ;@gateway 0 type=\"GATE-E1\"");
    EXPECT_EQ(firstError(";@gateway 1 type=\"GATE-X9\""),
              "2:1: @gateway type must be one of GATE-E1, GATE-E2, GATE-P1, GATE-P2, GATE-D1, "
              "GATE-D2, GATE-C1, GATE-C2, not 'GATE-X9'");
    EXPECT_EQ(firstError(";@gateway 1 type=\"GATE-E1\"\n;@gateway 1 type=\"GATE-E2\""),
              "3:1: @gateway 1: a gateway with this node address is already declared");
}

TEST(GatewayRecords, MergingTwoGatewaysOnOneNodeIsAConflict) {
    const auto ours = project::readProject(kProject);
    const auto theirs = project::readProject("$name Other\n"
                                             ";@gateway 3 type=\"GATE-D1\"\n"
                                             "! id_pluto:05=000000000005\n");
    const auto merged = project::mergeProjects(ours.project, theirs.project, false);
    EXPECT_FALSE(merged.merged);
    EXPECT_EQ(merged.conflicts, std::vector<std::string>{"gateway node 3 is in both projects"});
    const auto other = project::readProject("$name Other\n"
                                            ";@gateway 7 type=\"GATE-D1\"\n"
                                            "! id_pluto:05=000000000005\n");
    const auto joined = project::mergeProjects(ours.project, other.project, false);
    ASSERT_TRUE(joined.merged);
    EXPECT_EQ(joined.merged->gateways.size(), 3u);
}
