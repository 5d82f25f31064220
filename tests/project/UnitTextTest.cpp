// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/UnitText.h"
#include "ProjectText.h"
#include "project/ProjectFile.h"
#include "project/TextPlace.h"
#include "project/VariableTable.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

const char* kTextTwoUnits = "$name Two\n"
                            "\n"
                            "! id_pluto:00=000000000000\n"
                            ";@var M0.0 description=\"Muting\"\n"
                            "! id_pluto:01=000000000000\n"
                            "! I0.12=EStop\n"
                            "\n"
                            "! pgm_pluto:00\n"
                            "! M0.0=Muting\n"
                            "S0.0_0\n"
                            "Q0.2 = EStop * Muting\n"
                            "\n"
                            "! pgm_pluto:01\n"
                            "S1.0_0\n"
                            "Q1.2 = EStop\n";

} // namespace

TEST(UnitText, IsTheUnitsPartOfTheProjectText) {
    const project::Project p = projectFrom(kTextTwoUnits);
    EXPECT_EQ(project::unitText(p, 0), "! pgm_pluto:00\n"
                                       "! M0.0=Muting\n"
                                       "S0.0_0\n"
                                       "Q0.2 = EStop * Muting\n");
    EXPECT_EQ(project::unitText(p, 1), "! pgm_pluto:01\nS1.0_0\nQ1.2 = EStop\n");
    EXPECT_EQ(project::unitText(p, 7), "! pgm_pluto:07\n");
}

TEST(UnitText, ReadingItBackReplacesOnlyThatUnit) {
    const project::Project p = projectFrom(kTextTwoUnits);
    const auto read = project::readUnitText(p, 0,
                                            "! pgm_pluto:00\n"
                                            "! M0.0=Muting\n"
                                            ";@var M0.1 description=\"Fault\"\n"
                                            "! M0.1=Fault\n"
                                            "s0.0_0\n"
                                            "q0.2 = estop * muting * /fault\n");
    ASSERT_TRUE(read.ok()) << read.diagnostics.front().message;
    EXPECT_EQ(textOf(read.project), "$name Two\n"
                                    "\n"
                                    "! id_pluto:00=000000000000\n"
                                    ";@var M0.0 description=\"Muting\"\n"
                                    ";@var M0.1 description=\"Fault\"\n"
                                    "! id_pluto:01=000000000000\n"
                                    "! I0.12=EStop\n"
                                    "\n"
                                    "! pgm_pluto:00\n"
                                    "! M0.0=Muting\n"
                                    "! M0.1=Fault\n"
                                    "S0.0_0\n"
                                    "Q0.2 = EStop * Muting * /Fault\n"
                                    "\n"
                                    "! pgm_pluto:01\n"
                                    "S1.0_0\n"
                                    "Q1.2 = EStop\n");
    EXPECT_TRUE(isStable(read.project));
    // Its own text gives the project back.
    const auto same = project::readUnitText(p, 1, project::unitText(p, 1));
    ASSERT_TRUE(same.ok());
    EXPECT_TRUE(same.project == p);
    EXPECT_EQ(textOf(same.project), textOf(p));
}

TEST(UnitText, ErrorsAreReportedAtTheirLineInTheUnitsText) {
    const project::Project p = projectFrom(kTextTwoUnits);
    const auto read = project::readUnitText(p, 1,
                                            "! pgm_pluto:01\n"
                                            "S1.0_0\n"
                                            "Q1.2 = EStop +\n"
                                            "Q1.3 = Muting\n");
    ASSERT_EQ(read.diagnostics.size(), 2u);
    EXPECT_EQ(read.diagnostics[0].line, 3);
    EXPECT_EQ(read.diagnostics[1].line, 4); // Muting is unit 0's own name
    EXPECT_EQ(read.diagnostics[1].column, 8);
    EXPECT_FALSE(read.ok());
    EXPECT_TRUE(read.project == p);
}

TEST(UnitText, TheTextIsOneUnitsCodeAndNothingElse) {
    const project::Project p = projectFrom(kTextTwoUnits);
    auto read = project::readUnitText(p, 1, "S1.0_0\nQ1.2 = EStop\n");
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.diagnostics.front().line, 1);
    read = project::readUnitText(p, 1, "! pgm_pluto:00\nS0.0_0\n");
    ASSERT_FALSE(read.ok());
    read = project::readUnitText(p, 1, "! pgm_pluto:01\nS1.0_0\n! pgm_pluto:02\nS2.0_0\n");
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.diagnostics.back().line, 3);
    read = project::readUnitText(p, 1, "\n\n! pgm_pluto:01\nS1.0_0\n");
    EXPECT_TRUE(read.ok());
}

TEST(TextPlace, LinesOfTheProjectTextLeadToTheirPage) {
    const project::Project p = projectFrom(kTextTwoUnits);
    using Kind = project::TextPlace::Kind;
    // 1 $name, 2 blank, 3 id 00, 4 @var, 5 id 01, 6 I0.12=EStop, 7 blank,
    // 8 pgm 00, 9 M0.0=Muting, 10 S0.0_0, 11 Q0.2, 12 blank, 13 pgm 01, 14 S1.0_0, 15 Q1.2
    EXPECT_EQ(project::placeOfLine(p, 1).kind, Kind::Project);
    EXPECT_EQ(project::placeOfLine(p, 3), (project::TextPlace{Kind::Unit, 0, {}, 0}));
    EXPECT_EQ(project::placeOfLine(p, 5).station, 1);
    const auto variable = project::placeOfLine(p, 4);
    EXPECT_EQ(variable.kind, Kind::Variable);
    EXPECT_EQ(lang::toString(variable.address), "M0.0");
    EXPECT_EQ(lang::toString(project::placeOfLine(p, 6).address), "I0.12");
    EXPECT_EQ(project::placeOfLine(p, 11), (project::TextPlace{Kind::UnitCode, 0, {}, 4}));
    EXPECT_EQ(project::placeOfLine(p, 15), (project::TextPlace{Kind::UnitCode, 1, {}, 3}));
    EXPECT_EQ(project::placeOfLine(p, 99).kind, Kind::Project);
}
