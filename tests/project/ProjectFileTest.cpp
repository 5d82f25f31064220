// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/ProjectFile.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace rs;

namespace {

const char* kFileProject =
    "$name Press line\n"
    ";@project description=\"Two presses, one \\\"safe\\\" stop\\nsecond line\" "
    "include_source=yes\n"
    "! id_pluto:00=000000000000\n"
    ";@unit 00 description=\"Cabinet A\"\n"
    ";@var I0.0 description=\"Emergency stop, NC\"\n"
    "! id_pluto:01=000000000000\n"
    "! I0.0=EStop\n"
    "! pgm_pluto:00\n"
    ";@var M0.1 description=\"Latched fault\"\n"
    "S0.0_0\n"
    ";@network comment=\"Outputs\"\n"
    "Q0.2 = EStop\n"
    "Q0.3 = Q0.2\n";

} // namespace

TEST(ProjectFile, RecordsBecomeProjectFields) {
    auto result = project::readProject(kFileProject);
    ASSERT_TRUE(result.diagnostics.empty()) << result.diagnostics.front().message;
    const auto& p = result.project;
    EXPECT_EQ(p.name(), "Press line");
    EXPECT_EQ(p.description, "Two presses, one \"safe\" stop\nsecond line");
    EXPECT_TRUE(p.includeSource);
    EXPECT_EQ(p.unitDescriptions.at(0), "Cabinet A");
    EXPECT_EQ(p.variableDescriptions.at({lang::AddressKind::Input, 0, 0}), "Emergency stop, NC");
    EXPECT_EQ(p.variableDescriptions.at({lang::AddressKind::Memory, 0, 1}), "Latched fault");
    EXPECT_EQ(p.stations(), (std::vector<int>{0, 1}));
}

TEST(ProjectFile, SaveOpenSaveIsByteIdentical) {
    auto first = project::readProject(kFileProject);
    const std::string saved = project::writeProject(first.project);
    auto second = project::readProject(saved);
    ASSERT_TRUE(second.diagnostics.empty());
    EXPECT_TRUE(second.project == first.project);
    EXPECT_EQ(project::writeProject(second.project), saved);
    // Records sit in their canonical places: project after $name, unit and
    // variables after the unit's id declaration.
    EXPECT_EQ(saved.substr(0, saved.find("! id_pluto:01")),
              "$name Press line\n"
              ";@project description=\"Two presses, one \\\"safe\\\" stop\\nsecond line\" "
              "include_source=\"yes\"\n"
              "! id_pluto:00=000000000000\n"
              ";@unit 00 description=\"Cabinet A\"\n"
              ";@var I0.0 description=\"Emergency stop, NC\"\n"
              ";@var M0.1 description=\"Latched fault\"\n");
}

TEST(ProjectFile, EditedFieldsAreWritten) {
    auto result = project::readProject(kFileProject);
    result.project.description.clear();
    result.project.includeSource = false;
    result.project.unitDescriptions[1] = "Cabinet B";
    result.project.variableDescriptions[{lang::AddressKind::Output, 1, 2}] = "Motor \"B\"";
    const std::string saved = project::writeProject(result.project);
    EXPECT_EQ(saved.find(";@project"), std::string::npos);
    EXPECT_NE(saved.find("! id_pluto:01=000000000000\n;@unit 01 description=\"Cabinet B\"\n"
                         ";@var Q1.2 description=\"Motor \\\"B\\\"\"\n"),
              std::string::npos);
    auto reread = project::readProject(saved);
    EXPECT_EQ(reread.project.variableDescriptions.at({lang::AddressKind::Output, 1, 2}),
              "Motor \"B\"");
}

TEST(ProjectFile, NetworksGroupStatements) {
    auto result = project::readProject(kFileProject);
    const auto& step = result.project.program.units.at(0).steps.at(0);
    auto networks = project::networksOf(step);
    ASSERT_EQ(networks.size(), 1u);
    EXPECT_EQ(networks[0].comment, "Outputs");
    EXPECT_EQ(networks[0].lines.size(), 2u);

    auto plain = project::readProject("! pgm_pluto:00\nS0.0_0\nQ0.1 = I0.0\n; note\nQ0.2 = I0.1\n");
    auto single = project::networksOf(plain.project.program.units.at(0).steps.at(0));
    ASSERT_EQ(single.size(), 2u);
    EXPECT_EQ(single[0].lines.size(), 2u); // the statement and the comment under it
    EXPECT_EQ(single[1].lines.size(), 1u);
}

TEST(ProjectFile, AMalformedNetworkRecordIsAnOrdinaryComment) {
    auto result = project::readProject("! pgm_pluto:00\nS0.0_0\n;@network comment=\"open\n"
                                       "Q0.1 = I0.0\nQ0.2 = I0.1\n");
    EXPECT_EQ(lang::errorCount(result.diagnostics), 1);
    auto networks = project::networksOf(result.project.program.units.at(0).steps.at(0));
    EXPECT_EQ(networks.size(), 2u);
}

TEST(ProjectFile, MalformedAndUnknownRecords) {
    auto result = project::readProject("$name x\n"
                                       ";@project description=\"open\n"
                                       ";@unit 40 description=\"x\"\n"
                                       ";@gadget 1\n");
    ASSERT_EQ(result.diagnostics.size(), 3u);
    EXPECT_EQ(result.diagnostics[0].line, 2);
    EXPECT_EQ(result.diagnostics[0].message, "unterminated quoted value for 'description'");
    EXPECT_EQ(result.diagnostics[1].message,
              "@unit needs a station number 0-31, as in ;@unit 00 description=\"...\"");
    EXPECT_EQ(result.diagnostics[2].severity, lang::Severity::Warning);
    // Nothing is lost: what could not be read stays in the file as comments.
    const std::string saved = project::writeProject(result.project);
    EXPECT_NE(saved.find(";@project description=\"open\n"), std::string::npos);
    EXPECT_NE(saved.find(";@gadget 1\n"), std::string::npos);
}

TEST(ProjectFile, FilesAreWrittenAtomicallyAndReadErrorsNameTheFile) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath("p.sps");
    EXPECT_TRUE(project::writeTextFile(path, "Q\n").isEmpty());
    EXPECT_EQ(project::readTextFile(path).text, "Q\n");
    const QString missing = dir.filePath("missing.sps");
    auto read = project::readTextFile(missing);
    EXPECT_TRUE(read.error.startsWith("cannot read " + missing + ": ")) << read.error.toStdString();
    const QString blocked = dir.filePath("no/such/dir/p.sps");
    EXPECT_TRUE(project::writeTextFile(blocked, "x").startsWith("cannot write " + blocked));
}
