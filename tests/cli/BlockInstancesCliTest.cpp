// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProgramRun.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

using rs::test::runCli;
using rs::test::writeFile;

// Two instances of the shipped EquivalentInputs, written by hand without
// their statements.
const QByteArray kHandWritten =
    "! id_pluto:00=000000000000\n"
    "! type_pluto:00=A20,is3\n"
    "! I0.0=Door1A\n"
    "! I0.1=Door1B\n"
    "! pgm_pluto:00\n"
    "S0.0_0\n"
    ";@block EquivalentInputs Channel1=\"Door1A\" Channel2=\"Door1B\" Out=\"Q0.2\"\n"
    ";@end\n"
    ";@block EquivalentInputs Channel1=\"I0.2\" Channel2=\"I0.3\" Out=\"Q0.3\" "
    "DiscrepancyTime=\"1s00\"\n"
    ";@end\n";

TEST(BlockInstancesCli, FormatWritesTheExpansionsAndBothFilesCompileToTheSameImage) {
    QTemporaryDir dir;
    const QString original = writeFile(dir, "hand.sps", kHandWritten);
    const auto formatted = runCli({"format", original});
    ASSERT_EQ(formatted.exitCode, 0) << formatted.err.toStdString();
    EXPECT_TRUE(formatted.out.contains(
        ";@block EquivalentInputs Channel1=\"Door1A\" Channel2=\"Door1B\" Out=\"Q0.2\" "
        "lib=\"Rungsmith_Basics\" version=\"1.0\""))
        << formatted.out.toStdString();
    EXPECT_TRUE(formatted.out.contains("Q0.3 = I0.2 * I0.3 * /M0."));
    const QString expanded = writeFile(dir, "expanded.sps", formatted.out);

    const auto again = runCli({"format", expanded});
    EXPECT_EQ(again.out, formatted.out) << "the expanded file is canonical";

    const auto first =
        runCli({"compile", original, "-o", dir.filePath("a.hps"), "--no-io-warnings"});
    const auto second =
        runCli({"compile", expanded, "-o", dir.filePath("b.hps"), "--no-io-warnings"});
    ASSERT_EQ(first.exitCode, 0) << first.err.toStdString();
    ASSERT_EQ(second.exitCode, 0) << second.err.toStdString();
    EXPECT_EQ(rs::test::readFile(dir.filePath("a.hps")), rs::test::readFile(dir.filePath("b.hps")));

    const auto roundtrip = runCli({"roundtrip", expanded});
    EXPECT_EQ(roundtrip.exitCode, 0) << roundtrip.err.toStdString();
    EXPECT_EQ(roundtrip.out, formatted.out) << "instances stay instances through the ladder";
}

TEST(BlockInstancesCli, ABadCallIsAnErrorAtItsRecordAndNothingIsWritten) {
    QTemporaryDir dir;
    QByteArray text = kHandWritten;
    text.replace("Channel2=\"Door1B\"", "Chanel2=\"Door1B\"");
    const QString path = writeFile(dir, "bad.sps", text);
    const auto check = runCli({"check", path, "--no-io-warnings"});
    EXPECT_EQ(check.exitCode, 1);
    EXPECT_TRUE(check.errText().contains(
        path + ":7:44: error: EquivalentInputs: no pin 'Chanel2'; its pins are Channel1, "
               "Channel2, DiscrepancyTime, Out, Fault\n"))
        << check.err.toStdString();
    EXPECT_TRUE(check.errText().contains(
        path + ":7:1: error: EquivalentInputs: input Channel2 is not bound and has no default"));
    const auto format = runCli({"format", path});
    EXPECT_EQ(format.exitCode, 1);
    EXPECT_TRUE(format.out.isEmpty());
    EXPECT_EQ(rs::test::readFile(path), text);
}

const QByteArray kInstancesUserLibrary = "rungsmith-library 1\n"
                                         "library Mine\n"
                                         "version 1\n"
                                         "block Invert\n"
                                         "    kind macro\n"
                                         "    version 1\n"
                                         "    description en Out is the inverse of In.\n"
                                         "    pin In in bit primary\n"
                                         "    pin Out out bit primary\n"
                                         "    body {Out} = /{In}\n";

const QByteArray kInvert = "! id_pluto:00=000000000000\n"
                           "! pgm_pluto:00\n"
                           "S0.0_0\n"
                           ";@block Invert In=\"I0.0\" Out=\"Q0.2\"\n"
                           ";@end\n";

TEST(BlockInstancesCli, UserLibrariesComeFromTheProjectsFolderAndFromLib) {
    QTemporaryDir project;
    QTemporaryDir elsewhere;
    const QString path = writeFile(project, "invert.sps", kInvert);
    const auto unknown = runCli({"check", path, "--no-io-warnings"});
    EXPECT_EQ(unknown.exitCode, 1);
    EXPECT_TRUE(unknown.errText().contains(path + ":4:1: error: unknown block 'Invert'"))
        << unknown.err.toStdString();

    const QString library = writeFile(elsewhere, "mine.rslib", kInstancesUserLibrary);
    const auto given = runCli({"format", path, "--lib", library});
    EXPECT_EQ(given.exitCode, 0) << given.err.toStdString();
    EXPECT_TRUE(given.out.contains("lib=\"Mine\" version=\"1\"\nQ0.2 = /I0.0\n;@end\n"))
        << given.out.toStdString();

    writeFile(project, "mine.rslib", kInstancesUserLibrary);
    const auto found = runCli({"format", path});
    EXPECT_EQ(found.exitCode, 0) << found.err.toStdString();
    EXPECT_EQ(found.out, given.out);
}

TEST(BlockInstancesCli, AScenarioRunsOnTheExpandedInstances) {
    QTemporaryDir dir;
    const QString path = writeFile(dir, "hand.sps", kHandWritten);
    const QString scenario =
        writeFile(dir, "doors.scn",
                  "set Door1A 1\nset Door1B 1\nscans 2\nexpect Q0.2 1\n"
                  "set Door1B 0\nrun 600ms\nexpect Q0.2 0\n"
                  "set Door1B 1\nscans 2\nexpect Q0.2 0\n"
                  "set Door1A 0\nset Door1B 0\nscans 2\nset Door1A 1\nset Door1B 1\nscans 2\n"
                  "expect Q0.2 1\n");
    const auto run = runCli({"test", path, scenario, "--no-io-warnings"});
    EXPECT_EQ(run.exitCode, 0) << run.out.toStdString() << run.err.toStdString();
}

// A RegisterValid of the shipped Rungsmith_System, written by hand without
// its call.
const QByteArray kRegisterValid = "! id_pluto:00=000000000000\n"
                                  ";@var R0.5 export=\"yes\"\n"
                                  "! type_pluto:00=A20,is3\n"
                                  "! id_pluto:01=000000000001\n"
                                  "! type_pluto:01=A20,is3\n"
                                  "! pgm_pluto:00\n"
                                  "S0.0_0\n"
                                  "(R0.5 = 42)\n"
                                  "! pgm_pluto:01\n"
                                  "S1.0_0\n"
                                  ";@block RegisterValid Input=\"R0.5\" Valid=\"M1.1\"\n"
                                  ";@end\n";

TEST(BlockInstancesCli, ASystemBlocksCallIsWrittenAndCompilesToTheSameImage) {
    QTemporaryDir dir;
    const QString original = writeFile(dir, "valid.sps", kRegisterValid);
    const auto formatted = runCli({"format", original});
    ASSERT_EQ(formatted.exitCode, 0) << formatted.err.toStdString();
    EXPECT_TRUE(formatted.out.contains(
        ";@block RegisterValid Input=\"R0.5\" Valid=\"M1.1\" lib=\"Rungsmith_System\" "
        "version=\"1.0\" #pin.Value=\"R1.149\"\n"
        ";@system RegisterValid Input=\"R0.5\" Valid=\"M1.1\" Value=\"R1.149\"\n;@end\n"))
        << formatted.out.toStdString();
    const QString expanded = writeFile(dir, "expanded.sps", formatted.out);
    EXPECT_EQ(runCli({"format", expanded}).out, formatted.out);

    const auto first = runCli({"compile", original, "-o", dir.filePath("a.hps")});
    const auto second = runCli({"compile", expanded, "-o", dir.filePath("b.hps")});
    ASSERT_EQ(first.exitCode, 0) << first.err.toStdString();
    ASSERT_EQ(second.exitCode, 0) << second.err.toStdString();
    EXPECT_EQ(rs::test::readFile(dir.filePath("a.hps")), rs::test::readFile(dir.filePath("b.hps")));

    const auto roundtrip = runCli({"roundtrip", expanded});
    EXPECT_EQ(roundtrip.exitCode, 0) << roundtrip.err.toStdString();
    EXPECT_EQ(roundtrip.out, formatted.out) << "the call stays in its instance through the ladder";

    const QString scenario =
        writeFile(dir, "valid.scn", "scans 2\nexpect M1.1 1\nexpect R1.149 42\n");
    const auto run = runCli({"test", expanded, scenario});
    EXPECT_EQ(run.exitCode, 0) << run.out.toStdString() << run.err.toStdString();
}

TEST(BlockInstancesCli, AWrongSystemCallIsAnErrorAtItsOperand) {
    QTemporaryDir dir;
    QByteArray text = kRegisterValid;
    text.replace(";@block RegisterValid Input=\"R0.5\" Valid=\"M1.1\"\n;@end\n",
                 ";@system RegisterValid Input=\"R0.5\" Valid=\"R1.1\" Value=\"R1.2\"\n");
    const QString path = writeFile(dir, "wrong.sps", text);
    const auto check = runCli({"check", path});
    EXPECT_EQ(check.exitCode, 1);
    EXPECT_EQ(check.errText(),
              path + ":11:37: error: RegisterValid: operand Valid takes a bit, not R1.1\n")
        << check.err.toStdString();
}

} // namespace

namespace {

TEST(BlockInstancesCli, TwoInstancesOfOneBlockInOneUnitKeepStatesOfTheirOwn) {
    QTemporaryDir dir;
    const QString path = writeFile(dir, "hand.sps", kHandWritten);
    // The first pair disagrees past its 0.5 s and latches its fault; the
    // second, with 1 s, agrees throughout and stays on.
    const QString scenario = writeFile(dir, "two.scn",
                                       "set Door1A 1\nset Door1B 1\nset I0.2 1\nset I0.3 1\n"
                                       "scans 2\nexpect Q0.2 1\nexpect Q0.3 1\n"
                                       "set Door1B 0\nset I0.3 0\nrun 600ms\n"
                                       "set Door1B 1\nset I0.3 1\nscans 2\n"
                                       "expect Q0.2 0\nexpect Q0.3 1\n");
    const auto run = runCli({"test", path, scenario, "--no-io-warnings"});
    EXPECT_EQ(run.exitCode, 0) << run.out.toStdString() << run.err.toStdString();
}

TEST(BlockInstancesCli, TheLadderVerbDrawsAnInstanceAsItsBoxWithLiveValues) {
    QTemporaryDir dir;
    const QString path = writeFile(dir, "hand.sps", kHandWritten);
    const QString scenario =
        writeFile(dir, "on.scn", "set Door1A 1\nset Door1B 1\nscans 2\nexpect Q0.2 1\n");
    const QString svg = dir.filePath("box.svg");
    const auto drawn = runCli({"ladder", path, "--unit", "0", "--network", "1", "--scenario",
                               scenario, "-o", svg, "--no-io-warnings"});
    ASSERT_EQ(drawn.exitCode, 0) << drawn.err.toStdString();
    const QByteArray picture = rs::test::readFile(svg);
    for (const char* text : {"EquivalentInputs", "Channel1", "Channel2", "DiscrepancyTime", "Out",
                             "Fault", "Door1A", "(0s50)", "Two-channel equivalence check"})
        EXPECT_TRUE(picture.contains(text)) << text;
    // The pins driven on are drawn in the powered colour, which nothing is
    // drawn in when nothing runs.
    EXPECT_TRUE(picture.contains("#00963c"));
    const QString still = dir.filePath("still.svg");
    ASSERT_EQ(runCli({"ladder", path, "--unit", "0", "--network", "1", "-o", still}).exitCode, 0);
    EXPECT_FALSE(rs::test::readFile(still).contains("#00963c"));
}

} // namespace
