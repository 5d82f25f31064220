// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProgramRun.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

// `merge` (cli.md, "Verbs for review, change control and project work"; the
// manual's Merge Project, Part 1, 12.2), run on files in a temporary folder.

using rs::test::runCli;
using rs::test::writeFile;

namespace {

const QByteArray kFirst = "$name Line\n"
                          "! id_pluto:00=000000000000\n"
                          "! type_pluto:00=A20,is3\n"
                          "! I0.0=Input_zero\n"
                          "! pgm_pluto:00\n"
                          "S0.0_0\n"
                          "Q0.2 = Input_zero\n";

const QByteArray kSecond = "$name Cell\n"
                           "! id_pluto:01=000000000001\n"
                           "! type_pluto:01=A20,is3\n"
                           "! I1.0=Input_zero\n"
                           "! pgm_pluto:01\n"
                           "S1.0_0\n"
                           "Q1.2 = Input_zero\n";

TEST(MergeCli, ANameInBothIsAConflictAndNothingIsWritten) {
    QTemporaryDir dir;
    const QString out = dir.filePath("merged.sps");
    const auto run = runCli(
        {"merge", writeFile(dir, "a.sps", kFirst), writeFile(dir, "b.sps", kSecond), "-o", out});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.err.contains("the name 'Input_zero' is in both projects (I0.0, I1.0)"))
        << run.err.toStdString();
    EXPECT_FALSE(QFile::exists(out));
}

TEST(MergeCli, IgnoringConflictsWritesAProjectThatCompiles) {
    QTemporaryDir dir;
    const QString out = dir.filePath("merged.sps");
    const auto run = runCli({"merge", writeFile(dir, "a.sps", kFirst),
                             writeFile(dir, "b.sps", kSecond), "-o", out, "--ignore-conflicts"});
    EXPECT_EQ(run.exitCode, 0) << run.err.toStdString();
    EXPECT_TRUE(run.err.contains("kept only in the units that define it")) << run.err.toStdString();
    const auto check = runCli({"check", out});
    EXPECT_EQ(check.exitCode, 0) << check.err.toStdString();
    const QByteArray merged = rs::test::readFile(out);
    EXPECT_TRUE(merged.contains("$name Line")) << merged.toStdString();
    EXPECT_TRUE(merged.contains("Q1.2 = Input_zero")) << merged.toStdString();
}

TEST(MergeCli, AStationInBothIsRefusedEvenIgnoringConflicts) {
    QTemporaryDir dir;
    const QString a = writeFile(dir, "a.sps", kFirst);
    const auto run =
        runCli({"merge", a, a, "-o", dir.filePath("merged.sps"), "--ignore-conflicts"});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.err.contains("station 0 is in both projects")) << run.err.toStdString();
}

TEST(MergeCli, UsageAndUnreadableFilesExitTwo) {
    QTemporaryDir dir;
    EXPECT_EQ(runCli({"merge", writeFile(dir, "a.sps", kFirst)}).exitCode, 2);
    const auto missing =
        runCli({"merge", dir.filePath("none.sps"), writeFile(dir, "b.sps", kSecond), "-o",
                dir.filePath("merged.sps")});
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_TRUE(missing.err.contains("none.sps")) << missing.err.toStdString();
}

} // namespace
