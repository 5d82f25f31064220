// SPDX-License-Identifier: GPL-3.0-or-later
#include "LadderStyle.h"
#include "ManualNetworks.h"

#include "ProgramRun.h"
#include <QColor>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QProcessEnvironment>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

const QString kLadderMuting = QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps");

TEST(LadderCli, DrawsANetworkOfThePlcCodeAsPngAndSvg) {
    QTemporaryDir dir;
    const QString png = dir.filePath("net1.png");
    rs::test::ProgramRun run =
        rs::test::runCli({"ladder", kLadderMuting, "--unit", "0", "--network", "1", "-o", png});
    ASSERT_EQ(run.exitCode, 0) << run.errText().toStdString();
    EXPECT_TRUE(run.out.isEmpty());
    const QImage image(png);
    ASSERT_FALSE(image.isNull());
    // At twice the layout's size: the muting start circuit is 4 columns and an output.
    EXPECT_EQ(image.size(), QSize(2 * 656, 2 * 186));

    const QString svg = dir.filePath("net1.svg");
    ASSERT_EQ(
        rs::test::runCli({"ladder", kLadderMuting, "--unit", "0", "--network", "1", "-o", svg})
            .exitCode,
        0);
    QFile file(svg);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray text = file.readAll();
    for (const char* label : {"I0.12", "I0.13", "M0.0", "I0.14", "I0.2", "Q0.2", "Network 1"})
        EXPECT_TRUE(text.contains(label)) << label;
}

TEST(LadderCli, DrawsANetworkOfASequenceStep) {
    QTemporaryDir dir;
    const QString svg = dir.filePath("jump.svg");
    rs::test::ProgramRun run =
        rs::test::runCli({"ladder", kLadderMuting, "--unit", "0", "--sequence", "1", "--step", "2",
                          "--network", "3", "-o", svg});
    ASSERT_EQ(run.exitCode, 0) << run.errText().toStdString();
    QFile file(svg);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray text = file.readAll();
    EXPECT_TRUE(text.contains("step 0"));
    EXPECT_TRUE(text.contains("Network 3"));
}

TEST(LadderCli, UsageErrorsExitWith2) {
    QTemporaryDir dir;
    const QString png = dir.filePath("x.png");
    const QStringList bad[] = {
        {"ladder", kLadderMuting, "--network", "1", "-o", png}, // no unit
        {"ladder", kLadderMuting, "--unit", "0", "-o", png},    // no network
        {"ladder", kLadderMuting, "--unit", "0", "--network", "0", "-o",
         png}, // networks count from 1
        {"ladder", kLadderMuting, "--unit", "40", "--network", "1", "-o", png}, // no such station
        {"ladder", kLadderMuting, "--unit", "0", "--network", "1"},             // no output
        {"ladder", kLadderMuting, "--unit", "0", "--network", "1", "-o", dir.filePath("x.pdf")},
        {"ladder", kLadderMuting, "--unit", "0", "--sequence", "1", "--network", "1", "-o", png},
        {"ladder", "--unit", "0", "--network", "1", "-o", png}, // no file
        {"ladder", dir.filePath("missing.sps"), "--unit", "0", "--network", "1", "-o", png},
        {"ladder", kLadderMuting, "--unit", "0", "--network", "1", "-o", "/nonexistent-dir/x.png"},
        {"roundtrip"},
    };
    for (const auto& arguments : bad) {
        rs::test::ProgramRun run = rs::test::runCli(arguments);
        EXPECT_EQ(run.exitCode, 2) << arguments.join(' ').toStdString();
        EXPECT_FALSE(run.errText().isEmpty());
    }
    EXPECT_FALSE(QFile::exists(png));
}

TEST(LadderCli, WhatTheProjectDoesNotHaveExits1) {
    QTemporaryDir dir;
    const QString png = dir.filePath("x.png");
    struct Case {
        QStringList arguments;
        const char* message;
    };
    const Case cases[] = {
        {{"--unit", "5", "--network", "1"}, "unit 5 has no code"},
        {{"--unit", "0", "--sequence", "4", "--step", "0", "--network", "1"},
         "unit 0 has no step S0.4_0"},
        {{"--unit", "0", "--network", "4"}, "step S0.0_0 has 3 network(s), not 4"},
    };
    for (const auto& c : cases) {
        rs::test::ProgramRun run =
            rs::test::runCli(QStringList{"ladder", kLadderMuting, "-o", png} + c.arguments);
        EXPECT_EQ(run.exitCode, 1) << c.message;
        EXPECT_TRUE(run.errText().contains(c.message)) << run.errText().toStdString();
    }
    const QString broken = rs::test::writeFile(dir, "bad.sps", "! pgm_pluto:00\nS0.0_0\nQ0.1 = \n");
    rs::test::ProgramRun run =
        rs::test::runCli({"ladder", broken, "--unit", "0", "--network", "1", "-o", png});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.errText().contains("bad.sps:3:"));
    EXPECT_FALSE(QFile::exists(png));
}

// Step 1 of sequence 1 runs only after I0.3 took the sequence there.
const QByteArray kTwoSteps = "! id_pluto:00=000000000000\n! pgm_pluto:00\n"
                             "S0.0_0\nQ0.1 = I0.2\n"
                             "S0.1_0\nJ(+1) = I0.3\n"
                             "S0.1_1\nQ0.2 = I0.4\n";

// The style's powered colour, as the SVG spells it.
const QByteArray kPoweredInk = QColor(rs::render::LadderStyle{}.powered).name().toLatin1();

QByteArray drawAfter(const QTemporaryDir& dir, const QString& project, const QByteArray& scenario,
                     const QStringList& where) {
    static int count = 0;
    const QString name = QStringLiteral("s%1").arg(++count);
    const QString scn = rs::test::writeFile(dir, name + ".scn", scenario);
    const QString svg = dir.filePath(name + ".svg");
    rs::test::ProgramRun run = rs::test::runCli(
        QStringList{"ladder", project, "--scenario", scn, "-o", svg, "--unit", "0"} + where);
    EXPECT_EQ(run.exitCode, 0) << run.errText().toStdString() << run.out.toStdString();
    QFile file(svg);
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << name.toStdString();
    return file.readAll();
}

TEST(LadderCli, AfterAScenarioDrawsThePowerItLeaves) {
    QTemporaryDir dir;
    const QString project = rs::test::writeFile(dir, "steps.sps", kTwoSteps);
    const QStringList step1 = {"--sequence", "1", "--step", "1", "--network", "1"};
    const QByteArray ran =
        drawAfter(dir, project, "set I0.3 1\nset I0.4 1\nexpect Q0.2 1 within 30ms\n", step1);
    const QByteArray idle = drawAfter(dir, project, "run 30ms\nexpect Q0.2 0\n", step1);
    EXPECT_NE(ran, idle);
    EXPECT_TRUE(ran.contains(kPoweredInk)); // the active step's rung conducts
    EXPECT_FALSE(idle.contains(kPoweredInk)) << "a step that is not active did not run";

    const QStringList plcCode = {"--network", "1"};
    const QByteArray on =
        drawAfter(dir, project, "set I0.2 1\nexpect Q0.1 1 within 20ms\n", plcCode);
    const QByteArray off = drawAfter(dir, project, "run 20ms\nexpect Q0.1 0\n", plcCode);
    EXPECT_NE(on, off);
    EXPECT_GT(on.count(kPoweredInk), off.count(kPoweredInk)); // the rail is live in both
    const QString plain = dir.filePath("plain.svg");
    ASSERT_EQ(rs::test::runCli({"ladder", project, "--unit", "0", "--network", "1", "-o", plain})
                  .exitCode,
              0);
    QFile file(plain);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_FALSE(file.readAll().contains(kPoweredInk)); // without a scenario nothing runs
}

TEST(LadderCli, AFailedExpectationIsReportedAndTheEndStateStillDrawn) {
    QTemporaryDir dir;
    const QString project = rs::test::writeFile(dir, "steps.sps", kTwoSteps);
    const QString scn =
        rs::test::writeFile(dir, "wrong.scn", "set I0.2 1\nrun 20ms\nexpect Q0.1 0\n");
    const QString svg = dir.filePath("wrong.svg");
    rs::test::ProgramRun run = rs::test::runCli(
        {"ladder", project, "--unit", "0", "--network", "1", "--scenario", scn, "-o", svg});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.out.contains("wrong.scn:3:")) << run.out.toStdString();
    QFile file(svg);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_TRUE(file.readAll().contains(kPoweredInk));
}

TEST(LadderCli, AScenarioWithErrorsExits1AndDrawsNothing) {
    QTemporaryDir dir;
    const QString project = rs::test::writeFile(dir, "steps.sps", kTwoSteps);
    const QString svg = dir.filePath("x.svg");
    const QString bad = rs::test::writeFile(dir, "bad.scn", "set I0.2 1\nexpect NoSuchName 1\n");
    rs::test::ProgramRun run = rs::test::runCli(
        {"ladder", project, "--unit", "0", "--network", "1", "--scenario", bad, "-o", svg});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.errText().contains(QRegularExpression("bad\\.scn:2:\\d+: error: ")))
        << run.errText().toStdString();
    EXPECT_FALSE(QFile::exists(svg));

    const QString broken =
        rs::test::writeFile(dir, "broken.sps",
                            "! id_pluto:00=000000000000\n! pgm_pluto:00\nS0.0_0\n"
                            "Q0.1 = I0.2\nJ(+1) = I0.3\n");
    const QString fine = rs::test::writeFile(dir, "fine.scn", "expect Q0.1 0\n");
    run = rs::test::runCli(
        {"ladder", broken, "--unit", "0", "--network", "1", "--scenario", fine, "-o", svg});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.errText().contains("broken.sps:")) << run.errText().toStdString();
    EXPECT_FALSE(QFile::exists(svg));
}

TEST(LadderCli, AScenarioThatCannotBeReadExits2) {
    QTemporaryDir dir;
    const QString project = rs::test::writeFile(dir, "steps.sps", kTwoSteps);
    const QString svg = dir.filePath("x.svg");
    rs::test::ProgramRun run =
        rs::test::runCli({"ladder", project, "--unit", "0", "--network", "1", "--scenario",
                          dir.filePath("missing.scn"), "-o", svg});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.errText().contains("missing.scn")) << run.errText().toStdString();
    EXPECT_FALSE(QFile::exists(svg));
}

// The round trip through the ladder model prints exactly the canonical text,
// for every manual example and for a project with grouped networks.
TEST(RoundtripCli, PrintsTheCanonicalTextOfEveryManualExample) {
    for (const auto& path : rs::test::manualExamples()) {
        const QString file = QString::fromStdString(path.string());
        rs::test::ProgramRun format = rs::test::runCli({"format", file});
        rs::test::ProgramRun roundtrip = rs::test::runCli({"roundtrip", file});
        EXPECT_EQ(roundtrip.exitCode, 0) << path << roundtrip.errText().toStdString();
        EXPECT_EQ(roundtrip.out, format.out) << path;
    }
    QTemporaryDir dir;
    const QString grouped = rs::test::writeFile(
        dir, "grouped.sps",
        "! pgm_pluto:00\nS0.0_0\nM0.3 = I0.3\n;@network comment=\"Both \\\"outputs\\\"\"\n"
        "Q0.2 = I0.1 * (I0.2 + M0.0)   ; A\nQ0.3 = I0.1 * (I0.2 + M0.0)   ; B\n; note\n\n"
        ";@network comment=\"\"\nM0.0\nQ0.17\n");
    rs::test::ProgramRun format = rs::test::runCli({"format", grouped});
    rs::test::ProgramRun roundtrip = rs::test::runCli({"roundtrip", grouped});
    EXPECT_EQ(roundtrip.exitCode, 0) << roundtrip.errText().toStdString();
    EXPECT_EQ(roundtrip.out, format.out);
}

TEST(RoundtripCli, AProjectWithErrorsExits1) {
    QTemporaryDir dir;
    const QString broken =
        rs::test::writeFile(dir, "bad.sps", "! pgm_pluto:00\nS0.0_0\nQ0.1 = I0.1 +\n");
    rs::test::ProgramRun run = rs::test::runCli({"roundtrip", broken});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.errText().contains("bad.sps:3:"));
}

} // namespace
