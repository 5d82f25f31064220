// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/Sequences.h"
#include "ProjectText.h"

#include <gtest/gtest.h>

using namespace rs;

TEST(Sequences, ANewSequenceStandsAfterTheSequencesBeforeIt) {
    project::Project p = projectFrom("! id_pluto:00=000000000000\n"
                                     "! pgm_pluto:00\n"
                                     "S0.0_0\n"
                                     "Q0.2 = I0.1\n"
                                     "S0.3_0\n"
                                     "J(+1) = I0.2\n"
                                     "S0.3_1\n");
    EXPECT_EQ(project::sequencesOf(p, 0), (std::vector<int>{3}));
    ASSERT_FALSE(project::addSequence(p, 0, 1));
    ASSERT_FALSE(project::addSequence(p, 0, 9));
    EXPECT_EQ(textOf(p), "! id_pluto:00=000000000000\n"
                         "! pgm_pluto:00\n"
                         "S0.0_0\n"
                         "Q0.2 = I0.1\n"
                         "\n"
                         "S0.1_0\n"
                         "\n"
                         "S0.3_0\n"
                         "J(+1) = I0.2\n"
                         "S0.3_1\n"
                         "\n"
                         "S0.9_0\n");
    EXPECT_TRUE(isStable(p));
    EXPECT_EQ(project::sequencesOf(p, 0), (std::vector<int>{1, 3, 9}));
    EXPECT_EQ(project::freeSequences(p, 0).size(), 6u);
    EXPECT_TRUE(project::addSequence(p, 0, 3));
    EXPECT_TRUE(project::addSequence(p, 0, 0));
    EXPECT_TRUE(project::addSequence(p, 0, 10));
}
