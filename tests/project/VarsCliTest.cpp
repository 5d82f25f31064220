// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProgramRun.h"
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

const QString kMuting = QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps");

const QByteArray kVarsProject = "$name Vars\n"
                                "! id_pluto:00=000000000000\n"
                                "! I0.0=MuteSensor1\n"
                                "! pgm_pluto:00\n"
                                "S0.0_0\n"
                                "Q0.2 = MuteSensor1\n";

} // namespace

TEST(VarsCli, ExportWritesTheCsv) {
    QTemporaryDir dir;
    const QString project = rs::test::writeFile(dir, "p.sps", kVarsProject);
    const rs::test::ProgramRun run =
        rs::test::runCli({"vars", "export", project, "-o", dir.filePath("out.csv")});
    EXPECT_EQ(run.exitCode, 0) << run.errText().toStdString();
    EXPECT_EQ(rs::test::readFile(dir.filePath("out.csv")),
              "\xEF\xBB\xBFVariable,Symbolic Name,Description\r\nI0.0,MuteSensor1,\r\n");
}

TEST(VarsCli, ImportWritesTheProjectWithTheNewNames) {
    QTemporaryDir dir;
    const QString project = rs::test::writeFile(dir, "p.sps", kVarsProject);
    const QString csv = rs::test::writeFile(dir, "in.csv",
                                            "Variable;Symbolic Name;Description\n"
                                            "I0.0;Sensor1;left sensor\n");
    const QString out = dir.filePath("out.sps");
    const rs::test::ProgramRun run = rs::test::runCli({"vars", "import", project, csv, "-o", out});
    EXPECT_EQ(run.exitCode, 0) << run.errText().toStdString();
    EXPECT_EQ(rs::test::readFile(out), "$name Vars\n"
                                       "! id_pluto:00=000000000000\n"
                                       ";@var I0.0 description=\"left sensor\"\n"
                                       "! I0.0=Sensor1\n"
                                       "! pgm_pluto:00\n"
                                       "S0.0_0\n"
                                       "Q0.2 = Sensor1\n");
}

TEST(VarsCli, BadRowsAreErrorsByLineAndNothingIsWritten) {
    QTemporaryDir dir;
    const QString project = rs::test::writeFile(dir, "p.sps", kVarsProject);
    const QString csv =
        rs::test::writeFile(dir, "in.csv", "Variable,Symbolic Name\nI0.0,ok\nI0.1,9lives\n");
    const QString out = dir.filePath("out.sps");
    const rs::test::ProgramRun run = rs::test::runCli({"vars", "import", project, csv, "-o", out});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.errText().startsWith(csv + ":3:6: error: ")) << run.errText().toStdString();
    EXPECT_FALSE(QFile::exists(out));
}

TEST(VarsCli, ExportImportRoundTripOfTheManualsExample) {
    QTemporaryDir dir;
    const QString csv = dir.filePath("muting.csv");
    ASSERT_EQ(rs::test::runCli({"vars", "export", kMuting, "-o", csv}).exitCode, 0);
    const QString out = dir.filePath("muting.sps");
    const rs::test::ProgramRun run = rs::test::runCli({"vars", "import", kMuting, csv, "-o", out});
    EXPECT_EQ(run.exitCode, 0) << run.errText().toStdString();
    const rs::test::ProgramRun formatted = rs::test::runCli({"format", kMuting});
    EXPECT_EQ(rs::test::readFile(out), formatted.out);
}

TEST(VarsCli, UsageAndUnreadableFilesAreExitTwo) {
    QTemporaryDir dir;
    EXPECT_EQ(rs::test::runCli({"vars"}).exitCode, 2);
    EXPECT_EQ(rs::test::runCli({"vars", "export", kMuting}).exitCode, 2); // no -o
    EXPECT_EQ(rs::test::runCli({"vars", "frobnicate", kMuting, "-o", dir.filePath("x")}).exitCode,
              2);
    const rs::test::ProgramRun missing =
        rs::test::runCli({"vars", "export", dir.filePath("none.sps"), "-o", dir.filePath("x.csv")});
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_TRUE(missing.errText().contains("none.sps"));
    const rs::test::ProgramRun unwritable =
        rs::test::runCli({"vars", "export", kMuting, "-o", dir.filePath("no/x.csv")});
    EXPECT_EQ(unwritable.exitCode, 2);
}
