// SPDX-License-Identifier: GPL-3.0-or-later
// rungsmith-cli with the shipped Analog01 library: a project that reads a
// 4-20 mA input through a body-less ReadCurrent runs its scenarios.
#include "ProgramRun.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

using rs::test::runCli;
using rs::test::writeFile;

// The manual's frequency converter (Part 1, 9.2): 4 mA is 0, 20 mA is 488.
const QByteArray kConverter =
    "! id_pluto_Double:00=000000000000\n"
    "! type_pluto:00=D45,is3\n"
    "! R0.10=Speed_Freq_Conv\n"
    "! pgm_pluto:00\n"
    "! IA0.1,current\n"
    "S0.0_0\n"
    ";@block ReadCurrent Input=\"IA0.1\" Value_4mA=\"0\" Value_20mA=\"488\" Q=\"M0.1\" "
    "Scaled_Value=\"Speed_Freq_Conv\"\n"
    ";@end\n";

TEST(Analog01Cli, TestRunsTheManualsExampleWithAWireBreak) {
    QTemporaryDir dir;
    const QString project = writeFile(dir, "converter.sps", kConverter);
    const QString scenario = writeFile(dir, "converter.scn",
                                       "set IA0.1 20000\nscans 1\n"
                                       "expect M0.1 1\nexpect Speed_Freq_Conv 488\n"
                                       "set IA0.1 0\nscans 1\n"
                                       "expect M0.1 0\nexpect Speed_Freq_Conv -122\n");
    const auto run = runCli({"test", project, scenario});
    EXPECT_EQ(run.exitCode, 0) << run.out.toStdString() << run.err.toStdString();
    EXPECT_EQ(run.outText(), QStringLiteral("4 passed, 0 failed\n"));
}

TEST(Analog01Cli, AScenarioThatExpectsAnotherScaleFails) {
    QTemporaryDir dir;
    const QString project = writeFile(dir, "converter.sps", kConverter);
    const QString scenario =
        writeFile(dir, "wrong.scn", "set IA0.1 0\nscans 1\nexpect Speed_Freq_Conv 0\n");
    const auto run = runCli({"test", project, scenario});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.outText().contains(QStringLiteral("wrong.scn:3: expect Speed_Freq_Conv 0 "
                                                      "failed: got -122")))
        << run.out.toStdString();
}

TEST(Analog01Cli, BlocksListShowsTheFourBlocksWithTheirPins) {
    const auto run = runCli({"blocks", "list", "--lib", "Analog01"});
    EXPECT_EQ(run.exitCode, 0) << run.err.toStdString();
    EXPECT_EQ(run.outText(),
              QStringLiteral(
                  "Analog01 ReadVoltage(Input, Value_0V, Value_10V -> Q, [Voltage], Scaled_Value)\n"
                  "Analog01 ReadCurrent(Input, Value_4mA, Value_20mA -> Q, [Current], "
                  "Scaled_Value)\n"
                  "Analog01 ReadVoltage_32(Input, Value_0V, Value_10V -> Q, [Voltage], "
                  "Scaled_Value)\n"
                  "Analog01 ReadCurrent_32(Input, Value_4mA, Value_20mA -> Q, [Current], "
                  "Scaled_Value)\n"));
}

} // namespace
