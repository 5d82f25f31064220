// SPDX-License-Identifier: GPL-3.0-or-later
// rungsmith-cli with the shipped Rungsmith_Speed library: a project that
// counts a photocell's pulses and monitors the speed with body-less blocks
// runs its scenarios.
#include "ProgramRun.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

using rs::test::runCli;
using rs::test::writeFile;

// The photocell of the manual's example (Part 1, 9.2) on IA0.0, compared
// with a speed in R0.10 by SpeedMon1 with MaxDiff 20 and DiffDelay 0.5 s.
const QByteArray kPhotocell =
    "! id_pluto_Double:00=000000000000\n"
    "! type_pluto:00=D45,is3\n"
    "! R0.10=CompSpeed\n"
    "! R0.11=Speed_Photocell\n"
    "! pgm_pluto:00\n"
    "! IA0.0,counter_up\n"
    "S0.0_0\n"
    ";@block HS_SpeedCount_Up Input=\"IA0.0\" Valid=\"M0.1\" PulsePerSec=\"Speed_Photocell\"\n"
    ";@end\n"
    ";@block SpeedMon1 Speed=\"Speed_Photocell\" CompSpeed=\"CompSpeed\" MaxDiff=\"20\" "
    "DiffDelay=\"0s50\" LowSpeedLim=\"150\" SpeedValid=\"M0.2\" ValidSpeed=\"R0.12\" "
    "StandStill=\"M0.3\" SafeLowSpeed=\"M0.4\"\n"
    ";@end\n";

TEST(SpeedCli, TestRunsTheBlocksOnAPulseFrequency) {
    QTemporaryDir dir;
    const QString project = writeFile(dir, "photocell.sps", kPhotocell);
    const QString scenario = writeFile(dir, "photocell.scn",
                                       "scans 71\nexpect M0.3 1\n"
                                       "set IA0.0 488\nset CompSpeed 488\nscans 1\n"
                                       "expect M0.1 1\nexpect Speed_Photocell 488\n"
                                       "expect R0.12 488\nexpect M0.4 0\n"
                                       "set CompSpeed 467\nscans 51\n"
                                       "expect M0.2 0\nexpect R0.12 32767\n");
    const auto run = runCli({"test", project, scenario});
    EXPECT_EQ(run.exitCode, 0) << run.out.toStdString() << run.err.toStdString();
    EXPECT_EQ(run.outText(), QStringLiteral("7 passed, 0 failed\n"));
}

TEST(SpeedCli, AScenarioThatExpectsTheFaultTooEarlyFails) {
    QTemporaryDir dir;
    const QString project = writeFile(dir, "photocell.sps", kPhotocell);
    const QString scenario = writeFile(dir, "early.scn",
                                       "set IA0.0 488\nset CompSpeed 467\nscans 50\n"
                                       "expect M0.2 0\n");
    const auto run = runCli({"test", project, scenario});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.outText().contains(QStringLiteral("early.scn:4: expect M0.2 0 failed: got 1")))
        << run.out.toStdString();
}

TEST(SpeedCli, BlocksListShowsTheThreeBlocksWithTheirPins) {
    const auto run = runCli({"blocks", "list", "--lib", "Rungsmith_Speed"});
    EXPECT_EQ(run.exitCode, 0) << run.err.toStdString();
    EXPECT_EQ(run.outText(),
              QStringLiteral("Rungsmith_Speed HS_SpeedCount_Up(Input -> Valid, EdgePer10ms, "
                             "PulsePerSec)\n"
                             "Rungsmith_Speed HS_SpeedCount_Dir(Input_A, Input_B -> Valid, "
                             "EdgePer10ms, PulsePerSec)\n"
                             "Rungsmith_Speed SpeedMon1(Speed, CompSpeed, MaxDiff, DiffDelay, "
                             "LowSpeedLim -> SpeedValid, ValidSpeed, StandStill, "
                             "SafeLowSpeed)\n"));
}

} // namespace
