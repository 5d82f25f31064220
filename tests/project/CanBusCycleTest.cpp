// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/CanBusCycle.h"
#include "compiler/Compiler.h"
#include "compiler/ImageCodec.h"
#include "project/ProjectFile.h"
#include "project/UnitSettings.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

constexpr std::string_view kCanTwoUnits = "! id_pluto:00=000000000000\n"
                                          "! id_pluto:01=000000000001\n"
                                          "! type_pluto:00=A20,is3\n"
                                          "! type_pluto:01=A20,is3\n"
                                          "! pgm_pluto:00\n"
                                          "S0.0_0\n"
                                          "Q0.14 = I1.0\n";

std::string firstError(std::string_view unitRecord) {
    std::string text(kCanTwoUnits);
    text.insert(text.find("! type_pluto"), std::string(unitRecord) + "\n");
    for (const auto& d : project::readProject(text).diagnostics)
        if (d.severity == lang::Severity::Error)
            return std::to_string(d.line) + ":" + std::to_string(d.column) + ": " + d.message;
    return "no error";
}

} // namespace

TEST(CanBusCycle, KeptAsAUnitRecordOnlyWhenNotTheDefault) {
    auto read = project::readProject(kCanTwoUnits);
    EXPECT_EQ(project::canCycleOf(read.project, 1), 0);
    ASSERT_FALSE(project::setCanCycle(read.project, 1, 40));
    const std::string text = project::writeProject(read.project);
    EXPECT_NE(text.find("! id_pluto:01=000000000001\n;@unit 01 can_cycle_ms=\"40\"\n"),
              std::string::npos)
        << text;
    const auto again = project::readProject(text);
    EXPECT_TRUE(again.diagnostics.empty());
    EXPECT_EQ(project::canCycleOf(again.project, 1), 40);
    EXPECT_EQ(project::writeProject(again.project), text);
    // Back to the default: no record at all.
    ASSERT_FALSE(project::setCanCycle(read.project, 1, 0));
    EXPECT_EQ(project::writeProject(read.project).find("can_cycle_ms"), std::string::npos);
    // Removing the unit takes its cycle time with it.
    ASSERT_FALSE(project::setCanCycle(read.project, 1, 40));
    project::removeUnit(read.project, 1);
    EXPECT_EQ(project::canCycleOf(read.project, 1), 0);
}

TEST(CanBusCycle, AValueOutsideTheLimitsIsRefused) {
    project::Project p;
    EXPECT_EQ(project::setCanCycle(p, 0, 1001), "the CAN bus cycle time must be 1-1000 ms");
    EXPECT_FALSE(project::setCanCycle(p, 0, 1000));
    EXPECT_EQ(firstError(";@unit 01 can_cycle_ms=\"0\""),
              "3:1: @unit can_cycle_ms must be a number of milliseconds 1-1000, not '0'");
    EXPECT_EQ(firstError(";@unit 01 can_cycle_ms=\"20ms\""),
              "3:1: @unit can_cycle_ms must be a number of milliseconds 1-1000, not '20ms'");
    EXPECT_EQ(firstError(";@unit 01 can_cycle_ms=\"20\""), "no error");
}

TEST(CanBusCycle, TheImageCarriesItAndTheSignatureChangesOnlyWhenSet) {
    const auto plain = compiler::compileText(std::string(kCanTwoUnits));
    auto read = project::readProject(kCanTwoUnits);
    ASSERT_FALSE(project::setCanCycle(read.project, 0, 30));
    const auto slow = compiler::compile(read.project);
    ASSERT_EQ(slow.errors(), 0);
    ASSERT_EQ(slow.images.size(), 1u);
    EXPECT_EQ(slow.images[0].canCycleMs, 30);
    const auto decoded = compiler::decodeImage(compiler::encodeImage(slow.images[0]));
    ASSERT_TRUE(std::holds_alternative<compiler::UnitImage>(decoded));
    EXPECT_EQ(std::get<compiler::UnitImage>(decoded), slow.images[0]);
    EXPECT_NE(plain.signatures[0], slow.signatures[0]);
    EXPECT_EQ(plain.signatures[1], slow.signatures[1]);
}
