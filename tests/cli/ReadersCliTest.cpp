// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProgramRun.h"
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

// What `test` and `vars import` say about scenario and CSV files they refuse.
namespace {

const QByteArray kReadersProject = "! id_pluto:00=000000000000\n"
                                   "! I0.0=Start\n"
                                   "! pgm_pluto:00\n"
                                   "S0.0_0\n"
                                   "Q0.2 = Start\n";

} // namespace

TEST(ReadersCli, AScenarioThatExpectsNothingFails) {
    QTemporaryDir dir;
    const QString project = rs::test::writeFile(dir, "p.sps", kReadersProject);
    for (const QByteArray& text : {QByteArray(), QByteArray("\r\r"), QByteArray("set I0.0 1\n")}) {
        const QString scenario = rs::test::writeFile(dir, "s.scn", text);
        const rs::test::ProgramRun run = rs::test::runCli({"test", project, scenario});
        EXPECT_EQ(run.exitCode, 1) << text.toStdString();
        EXPECT_EQ(run.out, "0 passed, 1 failed\n");
        EXPECT_EQ(run.err, (scenario + ":1:1: error: no expectation: a scenario must check "
                                       "something\n")
                               .toUtf8());
    }
}

TEST(ReadersCli, AnEndlessScenarioIsRefusedBeforeItRuns) {
    QTemporaryDir dir;
    const QString project = rs::test::writeFile(dir, "p.sps", kReadersProject);
    const QString scenario = rs::test::writeFile(dir, "s.scn",
                                                 "\xEF\xBB\xBF"
                                                 "cycle 0ms\rrun 999999999min\rexpect Q0.2 0\r");
    const rs::test::ProgramRun run = rs::test::runCli({"test", project, scenario});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.out, "0 passed, 1 failed\n");
    EXPECT_EQ(run.err, (scenario + ":1:7: error: the scan cycle must be 1ms to 10s\n" + scenario +
                        ":2:5: error: a scenario runs at most 30 days of virtual time; this line "
                        "would pass that\n")
                           .toUtf8());
}

TEST(ReadersCli, CsvProblemsSayLineAndColumnAndNothingIsWritten) {
    QTemporaryDir dir;
    const QString project = rs::test::writeFile(dir, "p.sps", kReadersProject);
    const QString csv = rs::test::writeFile(dir, "in.csv",
                                            QByteArray("Variable,Symbolic Name,Description\n"
                                                       "I0.1,Stop,a\0b\n",
                                                       49));
    const QString out = dir.filePath("out.sps");
    const rs::test::ProgramRun run = rs::test::runCli({"vars", "import", project, csv, "-o", out});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.err, (csv + ":2:12: error: NUL byte: not text\n").toUtf8());
    EXPECT_FALSE(QFile::exists(out));
}
