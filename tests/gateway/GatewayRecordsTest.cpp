// SPDX-License-Identifier: GPL-3.0-or-later
#include "compiler/Compiler.h"
#include "compiler/ImageCodec.h"
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

TEST(GatewayRecords, SettingsAndAreasRoundTripAndOnlyNonDefaultsAreWritten) {
    const std::string text = "$name Line\n"
                             ";@gateway 0 type=\"GATE-E1\" cycle_ms=\"48\" timeout_ms=\"2000\" "
                             "to_pluto=\"0,1\" expected=\"0-3,5\"\n"
                             ";@gateway_area 0 5 pluto=\"2\" io_type=\"101\"\n"
                             ";@gateway_area 0 0 pluto=\"0\" io_type=\"7\"\n"
                             ";@gateway 1 type=\"GATE-P1\"\n"
                             "! id_pluto:00=000000000000\n";
    const auto read = project::readProject(text);
    ASSERT_TRUE(read.diagnostics.empty()) << read.diagnostics.front().message;
    const project::Gateway& gateway = read.project.gateways.at(0);
    EXPECT_EQ(gateway.cycleMs, 48);
    EXPECT_EQ(gateway.timeoutMs, 2000);
    EXPECT_EQ(gateway.toPluto, (std::set<int>{0, 1}));
    EXPECT_EQ(gateway.expectedNodes, (std::set<int>{0, 1, 2, 3, 5}));
    EXPECT_EQ(gateway.areas.at(5), (project::GatewayArea{2, 101}));
    const std::string written = project::writeProject(read.project);
    EXPECT_EQ(written.substr(0, written.find("! id_pluto")),
              "$name Line\n"
              ";@gateway 0 type=\"GATE-E1\" cycle_ms=\"48\" timeout_ms=\"2000\" to_pluto=\"0-1\" "
              "expected=\"0-3,5\"\n"
              ";@gateway_area 0 0 pluto=\"0\" io_type=\"7\"\n"
              ";@gateway_area 0 5 pluto=\"2\" io_type=\"101\"\n"
              ";@gateway 1 type=\"GATE-P1\"\n");
    EXPECT_EQ(project::writeProject(project::readProject(written).project), written);
}

TEST(GatewayRecords, SettingsOutsideTheManualsRangesAreErrors) {
    EXPECT_EQ(firstError(";@gateway 0 type=\"GATE-E1\" timeout_ms=\"500\""),
              "2:1: @gateway 0: the timeout is 0 (none) or 1000-60000 ms on an Ethernet gateway");
    EXPECT_EQ(firstError(";@gateway 0 type=\"GATE-P1\" timeout_ms=\"500\""), "no error");
    EXPECT_EQ(firstError(";@gateway 0 type=\"GATE-E1\" cycle_ms=\"300\""),
              "2:1: @gateway 0: the cycle time is 4-255 ms");
    EXPECT_EQ(firstError(";@gateway 0 type=\"GATE-E1\" to_pluto=\"4\""),
              "2:1: @gateway 0: Data to Pluto packets are numbered 0-3");
    EXPECT_EQ(firstError(";@gateway 0 type=\"GATE-E1\" expected=\"3-1\""),
              "2:1: @gateway expected must be numbers and runs such as 0-3,5, not '3-1'");
    EXPECT_EQ(firstError(";@gateway_area 0 5 pluto=\"2\" io_type=\"101\""),
              "2:1: @gateway_area 0: no gateway with this node address is declared before it");
    EXPECT_EQ(firstError(";@gateway 0 type=\"GATE-E1\"\n;@gateway_area 0 5 pluto=\"2\" "
                         "io_type=\"114\""),
              "3:1: @gateway_area 0: additional data area 5: the IO-type is 1-99 for a user "
              "block, 100-113 for a standard one");
    EXPECT_EQ(firstError(";@gateway 0 type=\"GATE-E1\"\n;@gateway_area 0 32 pluto=\"2\" "
                         "io_type=\"1\""),
              "3:1: @gateway_area needs a node address 0-15 and an area 0-31, as in "
              ";@gateway_area 0 5 pluto=\"2\" io_type=\"101\"");
}

// A unit's External communication setting (manual Part 1, 5.3): one record
// per block after the unit's declarations, into the image and back.
TEST(GatewayRecords, TheExternalCommunicationSettingIsKeptAndCompiledIntoTheImage) {
    const std::string text = "$name Line\n"
                             ";@gateway 0 type=\"GATE-E1\" to_pluto=\"0-3\"\n"
                             "! id_pluto:00=000000000000\n"
                             "! pgm_pluto:00\n"
                             ";@ext_comm 00 2 gateway=\"0\" packet=\"3\" timeout_ms=\"0\"\n"
                             ";@ext_comm 00 0 gateway=\"0\" packet=\"1\"\n"
                             "S0.0_0\n";
    const auto read = project::readProject(text);
    ASSERT_TRUE(read.diagnostics.empty()) << read.diagnostics.front().message;
    const project::ExternalComm expected{{0, {0, 1, project::kDefaultExternalTimeoutMs}},
                                         {2, {0, 3, 0}}};
    EXPECT_EQ(read.project.externalComm.at(0), expected);
    const std::string written = project::writeProject(read.project);
    EXPECT_NE(
        written.find("! id_pluto:00=000000000000\n;@ext_comm 00 0 gateway=\"0\" packet=\"1\"\n"
                     ";@ext_comm 00 2 gateway=\"0\" packet=\"3\" timeout_ms=\"0\"\n"),
        std::string::npos)
        << written;
    EXPECT_EQ(project::writeProject(project::readProject(written).project), written);

    const auto compiled = compiler::compile(read.project);
    ASSERT_EQ(compiled.errors(), 0);
    const auto& image = compiled.images.at(0);
    ASSERT_EQ(image.externalComm.size(), 2u);
    EXPECT_EQ(image.externalComm[1], (compiler::ExternalCommSetup{2, 0, 3, 0}));
    const auto decoded = compiler::decodeImage(compiler::encodeImage(image));
    ASSERT_TRUE(std::holds_alternative<compiler::UnitImage>(decoded));
    EXPECT_EQ(std::get<compiler::UnitImage>(decoded), image);
    // The setting is part of what the unit does: its signature changes.
    project::Project without = read.project;
    without.externalComm.clear();
    EXPECT_NE(compiler::compile(without).signatures, compiled.signatures);
}

TEST(GatewayRecords, AWrongExternalCommunicationRecordIsAnErrorAtItsLine) {
    const auto error = [](std::string_view record) {
        const std::string text = "$name Line\n! id_pluto:00=000000000000\n! pgm_pluto:00\n" +
                                 std::string(record) + "\nS0.0_0\n";
        for (const auto& d : project::readProject(text).diagnostics)
            if (d.severity == lang::Severity::Error)
                return std::to_string(d.line) + ": " + d.message;
        return std::string("no error");
    };
    EXPECT_EQ(error(";@ext_comm 00 4 gateway=\"0\" packet=\"0\""),
              "4: @ext_comm needs a station 0-31 and an External Comm Block 0-3, as in "
              ";@ext_comm 01 0 gateway=\"0\" packet=\"0\"");
    EXPECT_EQ(error(";@ext_comm 00 0 packet=\"0\""),
              "4: @ext_comm 00 0: the gateway node address must be 0-15");
    EXPECT_EQ(error(";@ext_comm 00 0 gateway=\"1\" packet=\"4\""),
              "4: @ext_comm 00 0: the packet must be 0-3");
    EXPECT_EQ(error(";@ext_comm 00 0 gateway=\"1\" packet=\"0\" timeout_ms=\"70000\""),
              "4: @ext_comm 00 0: the timeout must be 0 (none) to 60000 ms");
    EXPECT_EQ(error(";@ext_comm 00 0 gateway=\"1\" packet=\"0\"\n"
                    ";@ext_comm 00 0 gateway=\"2\" packet=\"0\""),
              "5: @ext_comm 00 0 is already given");
}
