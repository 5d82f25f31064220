// SPDX-License-Identifier: GPL-3.0-or-later
#include "review/UnitDiff.h"
#include "project/ProjectFile.h"

#include "TextEdit.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

using rs::test::replaced;

const char* kTwoUnits = "$name Two units\n"
                        "! id_pluto:00=000000000000\n"
                        "! type_pluto:00=A20,is3\n"
                        "! id_pluto:01=000000000001\n"
                        "! type_pluto:01=A20,is3\n"
                        "! pgm_pluto:00\n"
                        "! I0.0,a_pulse,non_inv\n"
                        "! Q0.10,a_pulse\n"
                        "! I0.1=Start\n"
                        "S0.0_0\n"
                        "Q0.2 = I0.0 * Start     ; the motor\n"
                        "! pgm_pluto:01\n"
                        "S1.0_0\n"
                        "Q1.2 = I1.0 * I1.1\n";

project::Project unitProject(const std::string& text) {
    project::ProjectReadResult result = project::readProject(text);
    EXPECT_TRUE(result.ok()) << text;
    return std::move(result.project);
}

std::vector<std::string> differences(const std::string& after) {
    std::vector<std::string> lines;
    for (const auto& difference :
         review::unitDifferences(unitProject(kTwoUnits), unitProject(after)))
        lines.push_back(difference.describe());
    return lines;
}

using Lines = std::vector<std::string>;

} // namespace

TEST(UnitDiff, TheSameProjectHasNone) {
    EXPECT_EQ(differences(kTwoUnits), Lines{});
    EXPECT_EQ(differences(project::writeProject(unitProject(kTwoUnits))), Lines{});
}

TEST(UnitDiff, EachKindOfChangeIsOneLineOfItsUnit) {
    EXPECT_EQ(differences(replaced(kTwoUnits, "a_pulse,non_inv", "a_pulse")),
              Lines{"Pluto 00 I/O options: changed"});
    EXPECT_EQ(differences(replaced(kTwoUnits, "a_pulse,non_inv", "non_inv,a_pulse")), Lines{});
    EXPECT_EQ(differences(replaced(kTwoUnits, "type_pluto:01=A20,is3", "type_pluto:01=A20,is2")),
              Lines{"Pluto 01 type: changed"});
    EXPECT_EQ(
        differences(replaced(kTwoUnits, "id_pluto:01=000000000001", "id_pluto:01=00000000000F")),
        Lines{"Pluto 01 ID code: changed"});
    EXPECT_EQ(
        differences(replaced(replaced(kTwoUnits, "! I0.1=Start", "! I0.1=Go"), "* Start", "* Go")),
        Lines{"Pluto 00 names and descriptions: changed"});
    EXPECT_EQ(differences(replaced(kTwoUnits, "; the motor", "; the pump")),
              Lines{"Pluto 00 comments: changed"});
    EXPECT_EQ(
        differences(replaced(kTwoUnits, "! id_pluto:00=000000000000\n",
                             "! id_pluto:00=000000000000\n;@unit 00 remanent=\"R100-R103\"\n")),
        Lines{"Pluto 00 exported and remanent variables: changed"});
}

TEST(UnitDiff, AnAddedOrRemovedUnitIsOneLine) {
    const std::string three = replaced(kTwoUnits, "! pgm_pluto:00\n",
                                       "! id_pluto:02=000000000002\n! type_pluto:02=B20,is3\n"
                                       "! pgm_pluto:00\n");
    EXPECT_EQ(differences(three), Lines{"Pluto 02 unit: added"});
    EXPECT_EQ(review::unitDifferences(unitProject(three), unitProject(kTwoUnits)).size(), 1u);
    EXPECT_EQ(review::unitDifferences(unitProject(three), unitProject(kTwoUnits))[0].describe(),
              "Pluto 02 unit: removed");
}
