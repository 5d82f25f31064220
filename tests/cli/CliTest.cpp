// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProgramRun.h"
#include "QtPrinting.h"
#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

const QString kCliMuting = QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps");

} // namespace

TEST(Cli, CheckOfAGoodProjectSaysResultOk) {
    rs::test::ProgramRun run = rs::test::runCli({"check", kCliMuting});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_EQ(run.outText(), "0 Error(s) detected Result=OK\n");
    // The manual's own example leaves the muting lamp Q0.17 without an I/O declaration.
    EXPECT_EQ(run.errText(), kCliMuting +
                                 ":37:1: warning: unconfigured I/O: Q0.17 has no I/O declaration "
                                 "in the code of unit 0\n");
    rs::test::ProgramRun quiet = rs::test::runCli({"check", "--no-io-warnings", kCliMuting});
    EXPECT_EQ(quiet.exitCode, 0);
    EXPECT_EQ(quiet.errText(), "");
}

TEST(Cli, CheckReportsEveryErrorWithFileLineAndColumn) {
    QTemporaryDir dir;
    QString path = rs::test::writeFile(
        dir, "bad.sps", "! pgm_pluto:00\nS0.0_0\nQ0.1 = I0.0 +\nQ0.2 = Nothing\nQ0.3 = (I0.1\n");
    rs::test::ProgramRun run = rs::test::runCli({"check", path});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.outText(), "3 Error(s) detected Result=FAILED\n");
    EXPECT_EQ(run.errText(), path + ":3:14: error: expected an operand after '+'\n" + path +
                                 ":4:8: error: unknown name 'Nothing': declare it with '! "
                                 "<address>=Nothing'\n" +
                                 path + ":5:13: error: expected ')', found the end of the line\n");
}

TEST(Cli, FormatPrintsCanonicalTextAndIsIdempotent) {
    rs::test::ProgramRun first = rs::test::runCli({"format", kCliMuting});
    ASSERT_EQ(first.exitCode, 0);
    EXPECT_TRUE(
        first.outText().contains("Q0.2 = I0.12 * (I0.13 + M0.0) * (P(I0.14) * I0.2 + Q0.2)\n"));
    QTemporaryDir dir;
    QString path = rs::test::writeFile(dir, "formatted.sps", first.outText().toUtf8());
    rs::test::ProgramRun second = rs::test::runCli({"format", path});
    EXPECT_EQ(second.exitCode, 0);
    EXPECT_EQ(second.outText(), first.outText());
}

TEST(Cli, FormatRefusesAProjectWithErrors) {
    QTemporaryDir dir;
    QString path = rs::test::writeFile(dir, "bad.sps", "! pgm_pluto:00\nS0.0_0\nQ0.1 = \n");
    rs::test::ProgramRun run = rs::test::runCli({"format", path});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.outText(), "");
    EXPECT_TRUE(run.errText().startsWith(path + ":3:")) << run.errText().toStdString();
}

TEST(Cli, UnreadableFilesAndUsageErrorsExitWithTwo) {
    rs::test::ProgramRun missing = rs::test::runCli({"check", "/nonexistent/x.sps"});
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_TRUE(missing.errText().contains("cannot read /nonexistent/x.sps"))
        << missing.errText().toStdString();
    EXPECT_EQ(rs::test::runCli({}).exitCode, 2);
    EXPECT_EQ(rs::test::runCli({"frobnicate", kCliMuting}).exitCode, 2);
    EXPECT_EQ(rs::test::runCli({"check"}).exitCode, 2);
    EXPECT_EQ(rs::test::runCli({"check", "--bogus", kCliMuting}).exitCode, 2);
}

TEST(Cli, CompileWritesTheImageBesideTheProjectOrWhereAsked) {
    QTemporaryDir dir;
    QFile::copy(kCliMuting, dir.filePath("muting.sps"));
    rs::test::ProgramRun beside = rs::test::runCli({"compile", dir.filePath("muting.sps")});
    EXPECT_EQ(beside.exitCode, 0);
    EXPECT_EQ(beside.outText(), "0 Error(s) detected Result=OK\n");
    QFile image(dir.filePath("muting.hps"));
    ASSERT_TRUE(image.open(QIODevice::ReadOnly));
    const QByteArray hex = image.readAll();
    EXPECT_TRUE(hex.startsWith(":10000000525349"));
    EXPECT_TRUE(hex.endsWith(":00000001FF\n"));

    rs::test::ProgramRun asked =
        rs::test::runCli({"compile", kCliMuting, "-o", dir.filePath("out.hps")});
    EXPECT_EQ(asked.exitCode, 0);
    QFile out(dir.filePath("out.hps"));
    ASSERT_TRUE(out.open(QIODevice::ReadOnly));
    EXPECT_EQ(out.readAll(), hex);
}

TEST(Cli, CompileWritesNothingWhenThereAreErrors) {
    QTemporaryDir dir;
    QString path = rs::test::writeFile(
        dir, "bad.sps", "! id_pluto:00=000000000000\n! pgm_pluto:00\nS0.0_0\nJ(+1) = I0.0\n");
    rs::test::ProgramRun run = rs::test::runCli({"compile", path});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.outText(), "1 Error(s) detected Result=FAILED\n");
    EXPECT_TRUE(run.errText().startsWith(path + ":4:1: error: J(+1) in the PLC code"))
        << run.errText().toStdString();
    EXPECT_FALSE(QFile::exists(dir.filePath("bad.hps")));
    rs::test::ProgramRun unwritable =
        rs::test::runCli({"compile", kCliMuting, "-o", "/nonexistent/dir/x.hps"});
    EXPECT_EQ(unwritable.exitCode, 2);
    EXPECT_TRUE(unwritable.errText().contains("cannot write /nonexistent/dir/x.hps"));
}

TEST(Cli, HelpAndVersion) {
    rs::test::ProgramRun help = rs::test::runCli({"--help"});
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_TRUE(help.outText().contains("check FILE.sps"));
    rs::test::ProgramRun version = rs::test::runCli({"--version"});
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_TRUE(version.outText().startsWith("rungsmith-cli "));
}
