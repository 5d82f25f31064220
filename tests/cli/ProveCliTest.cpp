// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProgramRun.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

// `prove` (properties.md), run on files in a temporary folder: its lines,
// its exit status, and counterexamples that `test` reproduces.

using rs::test::readFile;
using rs::test::runCli;
using rs::test::writeFile;

namespace {

const QByteArray kStop = "$name Stop\n"
                         "! id_pluto:00=000000000000\n"
                         "! type_pluto:00=A20,is3\n"
                         "! I0.12=EStop\n"
                         "! IQ0.14=Reset\n"
                         "! pgm_pluto:00\n"
                         "S0.0_0\n"
                         "Q0.2 = EStop * (N(Reset) + Q0.2)\n"
                         "Q0.3 = Q0.2 * TON(0s03)\n";

TEST(ProveCli, ProvedFailedUnknownAndCoveredLines) {
    QTemporaryDir dir;
    const QString project = writeFile(dir, "stop.sps", kStop);
    const QString props = writeFile(dir, "stop.prop",
                                    "; the stop circuit\n"
                                    "always Q0.2 -> EStop\n"
                                    "never Q0.3\n"
                                    "always /EStop -> within 20ms /Q0.2 * /Q0.3\n"
                                    "always Q0.3 -> (R0.1 >= 0)\n"
                                    "cover Q0.3\n");
    const QString cex = dir.filePath("cex");
    const auto run = runCli({"prove", project, props, "--cex", cex});
    EXPECT_EQ(run.exitCode, 1) << run.err.toStdString();
    // Reset held in the first scan, released in the second (the start), then
    // the on-delay's three ticks.
    EXPECT_EQ(run.outText().toStdString(),
              ("stop.prop:2: proved\n"
               "stop.prop:3: failed: counterexample of 5 scans in " +
               QDir::cleanPath(cex) + "/stop-3.scn\n" +
               "stop.prop:4: proved\n"
               "stop.prop:5: proved\n"
               "stop.prop:6: covered in 5 scans: " +
               QDir::cleanPath(cex) + "/stop-6.scn\n" + "4 proved, 1 failed, 0 unknown\n")
                  .toStdString());
    const QByteArray scenario = readFile(cex + "/stop-3.scn");
    // It names the inputs, changes only what the violation needs, and fails on its last line.
    EXPECT_TRUE(scenario.endsWith("set EStop 1\nset Reset 1\nscans 1\nset Reset 0\nscans 4\n"
                                  "expect Q0.3 0\n"))
        << scenario.toStdString();
    const int lines = static_cast<int>(scenario.count('\n'));
    const auto test = runCli({"test", project, cex + "/stop-3.scn"});
    EXPECT_EQ(test.exitCode, 1);
    EXPECT_TRUE(test.outText().startsWith(cex + "/stop-3.scn:" + QString::number(lines) + ": "))
        << test.out.toStdString();
    EXPECT_TRUE(test.outText().endsWith("0 passed, 1 failed\n"));
    // The witness holds.
    EXPECT_EQ(runCli({"test", project, cex + "/stop-6.scn"}).exitCode, 0);
}

TEST(ProveCli, UnknownWhenTheDepthRunsOut) {
    QTemporaryDir dir;
    const QString project = writeFile(dir, "count.sps",
                                      "! id_pluto:00=000000000000\n! type_pluto:00=A20,is3\n"
                                      "! pgm_pluto:00\nS0.0_0\n(R0.1++) = P(I0.0)\n");
    const QString props = writeFile(dir, "count.prop", "never (R0.1 >= 30)\n");
    const auto run = runCli({"prove", project, props, "--depth", "10"});
    EXPECT_EQ(run.exitCode, 3);
    EXPECT_EQ(run.outText(), "count.prop:1: unknown: no counterexample within 10 scans\n"
                             "0 proved, 0 failed, 1 unknown\n");
}

TEST(ProveCli, ASyntaxErrorIsADiagnosticAndExitOne) {
    QTemporaryDir dir;
    const QString project = writeFile(dir, "stop.sps", kStop);
    const QString props = writeFile(dir, "bad.prop", "always Q0.2\nalways Q0.2 -> \n");
    const auto run = runCli({"prove", project, props});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.outText().toStdString(),
              (props + ":2:15: error: expected an operand at the end of the line\n").toStdString());
}

TEST(ProveCli, UsageAndUnreadableFiles) {
    QTemporaryDir dir;
    const QString project = writeFile(dir, "stop.sps", kStop);
    EXPECT_EQ(runCli({"prove", project}).exitCode, 2);
    EXPECT_EQ(runCli({"prove", project, dir.filePath("missing.prop")}).exitCode, 2);
    const QString props = writeFile(dir, "p.prop", "never Q0.2\n");
    EXPECT_EQ(runCli({"prove", project, props, "--depth", "0"}).exitCode, 2);
    EXPECT_EQ(runCli({"prove", project, props, "--depth", "many"}).exitCode, 2);
}

// A system block's outputs are free in the model: a property that does not
// depend on them is proved; one whose only counterexample needs a gateway's
// data is unknown, and says why; one the simulator repeats fails.
TEST(ProveCli, SystemBlocksAreLeftFree) {
    QTemporaryDir dir;
    const QString props = writeFile(dir, "gw.prop",
                                    "always ContactorK1 -> EStopA * EStopB\n"
                                    "never M0.10\n"
                                    "always DriveEnable -> GM0.0\n");
    const auto run = runCli({"prove", QStringLiteral(RUNGSMITH_EXAMPLES "/gateway-line.sps"), props,
                             "--cex", dir.path()});
    EXPECT_EQ(run.exitCode, 1);
    const QStringList lines = run.outText().split('\n');
    ASSERT_GE(lines.size(), 4);
    EXPECT_EQ(lines[0], "gw.prop:1: proved");
    EXPECT_TRUE(lines[1].startsWith("gw.prop:2: failed: counterexample of 1 scans in "));
    EXPECT_TRUE(lines[2].startsWith("gw.prop:3: unknown: the counterexample of 2 scans needs "
                                    "values the prover leaves free"));
    EXPECT_TRUE(lines[2].contains("unit 1 line 58: the outputs of ExtVarBlock"))
        << lines[2].toStdString();
}

// The examples prove what their property files say, and the deliberately
// wrong one fails with a counterexample that replays.
TEST(ProveCli, TheExamplesAsShipped) {
    QTemporaryDir dir;
    const QString examples = QStringLiteral(RUNGSMITH_EXAMPLES);
    const struct {
        const char* name;
        int exitCode;
    } cases[] = {{"estop", 0}, {"two-hand", 0}, {"muting-wrong", 1}};
    for (const auto& example : cases) {
        const QString name = QString::fromUtf8(example.name);
        const auto run = runCli({"prove", examples + "/" + name + ".sps",
                                 examples + "/" + name + ".prop", "--cex", dir.path()});
        EXPECT_EQ(run.exitCode, example.exitCode) << run.out.toStdString();
        EXPECT_FALSE(run.outText().contains("unknown:")) << run.out.toStdString();
    }
    const auto test =
        runCli({"test", examples + "/muting-wrong.sps", dir.filePath("muting-wrong-4.scn")});
    EXPECT_EQ(test.exitCode, 1);
    EXPECT_TRUE(test.outText().contains("expect LightCurtain 1 failed")) << test.out.toStdString();
}

} // namespace
