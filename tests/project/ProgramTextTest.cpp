// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/ProgramText.h"
#include "ProjectText.h"

#include <gtest/gtest.h>

using namespace rs;

TEST(ProgramText, IsTheLanguageWithoutRecords) {
    const project::Project p = projectFrom("$name Press\n"
                                           ";@project description=\"Two presses\"\n"
                                           "\n"
                                           "! id_pluto:00=000000000000\n"
                                           ";@unit 00 description=\"Cabinet\" remanent=\"R100\"\n"
                                           ";@var I0.0 description=\"Stop\" \n"
                                           "! I0.0=EStop                   ; stop button\n"
                                           "\n"
                                           "! pgm_pluto:00\n"
                                           "S0.0_0\n"
                                           ";@network comment=\"Outputs\"\n"
                                           "\n"
                                           "Q0.2 = EStop\n"
                                           "Q0.3 = Q0.2\n");
    EXPECT_EQ(project::programText(p), "$name Press\n"
                                       "\n"
                                       "! id_pluto:00=000000000000\n"
                                       "! I0.0=EStop                   ; stop button\n"
                                       "\n"
                                       "! pgm_pluto:00\n"
                                       "S0.0_0\n"
                                       "\n"
                                       "Q0.2 = EStop\n"
                                       "Q0.3 = Q0.2\n");
}
