// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectText.h"
#include "project/ProjectFile.h"

#include <gtest/gtest.h>

using namespace rs;
using lang::Address;
using lang::AddressKind;

namespace {

const char* kWithAttributes = "$name Press\n"
                              "\n"
                              "! id_pluto_Double:00=000000000000\n"
                              ";@unit 00 description=\"Cabinet\" remanent=\"M100-M103,R100,R131\"\n"
                              ";@var M0.3 export=\"yes\"\n"
                              ";@var R0.7 description=\"Speed\" export=\"yes\"\n"
                              "! type_pluto:00=B46,is3\n"
                              "\n"
                              "! pgm_pluto:00\n"
                              "\n"
                              "S0.0_0\n"
                              "M0.3 = I0.0\n";

} // namespace

TEST(ProjectFileRecords, ExportAndRemanentAttributesAreRead) {
    const project::Project p = projectFrom(kWithAttributes);
    EXPECT_EQ(p.unitDescriptions.at(0), "Cabinet");
    const std::set<Address> remanent{
        {AddressKind::Memory, 0, 100},   {AddressKind::Memory, 0, 101},
        {AddressKind::Memory, 0, 102},   {AddressKind::Memory, 0, 103},
        {AddressKind::Register, 0, 100}, {AddressKind::Register, 0, 131}};
    EXPECT_EQ(p.remanentVariables, remanent);
    EXPECT_EQ(p.exportedVariables,
              (std::set<Address>{{AddressKind::Memory, 0, 3}, {AddressKind::Register, 0, 7}}));
    EXPECT_EQ(p.variableDescriptions.at({AddressKind::Register, 0, 7}), "Speed");
    EXPECT_FALSE(p.variableDescriptions.count({AddressKind::Memory, 0, 3}));
}

TEST(ProjectFileRecords, SaveOpenSaveIsByteIdentical) {
    const project::Project p = projectFrom(kWithAttributes);
    EXPECT_EQ(textOf(p), kWithAttributes);
    EXPECT_TRUE(isStable(p));
}

TEST(ProjectFileRecords, AttributesWithoutADescriptionMakeARecordOfTheirOwn) {
    project::Project p = projectFrom("! id_pluto:03=000000000000\n! pgm_pluto:03\nS3.0_0\n");
    p.remanentVariables.insert({AddressKind::Register, 3, 120});
    p.exportedVariables.insert({AddressKind::Memory, 3, 9});
    EXPECT_EQ(textOf(p), "! id_pluto:03=000000000000\n"
                         ";@unit 03 remanent=\"R120\"\n"
                         ";@var M3.9 export=\"yes\"\n"
                         "! pgm_pluto:03\n"
                         "S3.0_0\n");
    EXPECT_TRUE(isStable(p));
}

TEST(ProjectFileRecords, RunsAreReadInAnyOrderAndCase) {
    const project::Project p = projectFrom("! id_pluto:00=000000000000\n"
                                           ";@unit 00 remanent=r102-r103,m100\n"
                                           "! pgm_pluto:00\nS0.0_0\n");
    EXPECT_EQ(project::writeProject(p), "! id_pluto:00=000000000000\n"
                                        ";@unit 00 remanent=\"M100,R102-R103\"\n"
                                        "! pgm_pluto:00\n"
                                        "S0.0_0\n");
}

TEST(ProjectFileRecords, MalformedAttributesAreErrorsAtTheirLine) {
    auto read = project::readProject("! id_pluto:00=000000000000\n"
                                     ";@unit 00 remanent=\"R99-R101\"\n"
                                     ";@var M0.1 export=\"maybe\"\n"
                                     "! pgm_pluto:00\nS0.0_0\n");
    ASSERT_EQ(read.diagnostics.size(), 2u);
    EXPECT_EQ(read.diagnostics[0].line, 2);
    EXPECT_NE(read.diagnostics[0].message.find("R99"), std::string::npos);
    EXPECT_EQ(read.diagnostics[1].line, 3);
    EXPECT_NE(read.diagnostics[1].message.find("maybe"), std::string::npos);
}

TEST(ProjectFileRecords, FilesWithoutTheNewAttributesAreWrittenAsBefore) {
    const std::string text = "$name Press line\n"
                             ";@project description=\"Two presses\"\n"
                             "! id_pluto:00=000000000000\n"
                             ";@unit 00 description=\"Cabinet A\"\n"
                             ";@var I0.0 description=\"Emergency stop, NC\"\n"
                             "! I0.0=EStop\n"
                             "! pgm_pluto:00\n"
                             "S0.0_0\n"
                             "Q0.2 = EStop\n";
    EXPECT_EQ(textOf(projectFrom(text)), text);
}
