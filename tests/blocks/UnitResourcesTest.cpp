// SPDX-License-Identifier: GPL-3.0-or-later
#include "blocks/UnitResources.h"
#include "project/ProjectFile.h"

#include <gtest/gtest.h>

// A unit's timers, memories and registers, with those its block instances take.

using namespace rs;
using blocks::ResourceUse;

namespace {

project::Project resourcesProject(const std::string& code) {
    project::ProjectReadResult read = project::readProject("! id_pluto:00=000000000000\n"
                                                           "! type_pluto:00=A20,is3\n"
                                                           "! pgm_pluto:00\n"
                                                           "S0.0_0\n" +
                                                           code);
    EXPECT_TRUE(read.ok()) << (read.diagnostics.empty() ? "" : read.diagnostics[0].message);
    return read.project;
}

TEST(UnitResources, CountTheInstancesStatementsAndTheirPrivateVariables) {
    const auto resources = blocks::unitResources(
        resourcesProject(
            "M0.1 = I0.0 * TON(1s00) + I0.1 * /TOF(2s00)\n"
            "(R0.4 = 2)\n"
            ";@block EquivalentInputs Channel1=\"I0.0\" Channel2=\"I0.1\" Out=\"M0.1\" "
            "#pin.Fault=\"M0.599\" #fault=\"M0.598\" #count=\"DR0.148\"\n"
            "S(M0.598) = (I0.0 * /I0.1 + /I0.0 * I0.1) * TON(0s50)\n"
            "Q0.2 = M0.1 * /M0.598\n"
            ";@end\n"),
        0);
    EXPECT_EQ(resources.timers, (ResourceUse{3, 1, 50}));
    EXPECT_EQ(resources.memories, (ResourceUse{3, 2, 600}))
        << "M0.1 bound to a pin is the unit's own; M0.599 counts though no statement uses it";
    EXPECT_EQ(resources.registers, (ResourceUse{3, 2, 150})) << "a double register takes two";
}

TEST(UnitResources, AUnitWithoutCodeTakesNothing) {
    const auto resources = blocks::unitResources(resourcesProject(""), 0);
    EXPECT_EQ(resources.timers, (ResourceUse{0, 0, 50}));
    EXPECT_EQ(resources.memories.used, 0);
    EXPECT_EQ(resources.registers.used, 0);
}

} // namespace
