#include "ManualNetworks.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

struct CliRun {
    int exitCode = -1;
    QByteArray out;
    QString err;
};

CliRun cli(const QStringList& arguments) {
    QProcess process;
    process.start(QStringLiteral(RUNGSMITH_CLI), arguments);
    process.waitForFinished(60000);
    return {process.exitCode(), process.readAllStandardOutput(),
            QString::fromUtf8(process.readAllStandardError())};
}

const QString kMuting = QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps");

QString writeTemp(const QTemporaryDir& dir, const QString& name, const QByteArray& text) {
    QFile file(dir.filePath(name));
    EXPECT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(text);
    return file.fileName();
}

TEST(LadderCli, DrawsANetworkOfThePlcCodeAsPngAndSvg) {
    QTemporaryDir dir;
    const QString png = dir.filePath("net1.png");
    CliRun run = cli({"ladder", kMuting, "--unit", "0", "--network", "1", "-o", png});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    EXPECT_TRUE(run.out.isEmpty());
    const QImage image(png);
    ASSERT_FALSE(image.isNull());
    // At twice the layout's size: the muting start circuit is 4 columns and an output.
    EXPECT_EQ(image.size(), QSize(2 * 656, 2 * 186));

    const QString svg = dir.filePath("net1.svg");
    ASSERT_EQ(cli({"ladder", kMuting, "--unit", "0", "--network", "1", "-o", svg}).exitCode, 0);
    QFile file(svg);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray text = file.readAll();
    for (const char* label : {"I0.12", "I0.13", "M0.0", "I0.14", "I0.2", "Q0.2", "Network 1"})
        EXPECT_TRUE(text.contains(label)) << label;
}

TEST(LadderCli, DrawsANetworkOfASequenceStep) {
    QTemporaryDir dir;
    const QString svg = dir.filePath("jump.svg");
    CliRun run = cli({"ladder", kMuting, "--unit", "0", "--sequence", "1", "--step", "2",
                      "--network", "3", "-o", svg});
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
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
        {"ladder", kMuting, "--network", "1", "-o", png},                 // no unit
        {"ladder", kMuting, "--unit", "0", "-o", png},                    // no network
        {"ladder", kMuting, "--unit", "0", "--network", "0", "-o", png},  // networks count from 1
        {"ladder", kMuting, "--unit", "40", "--network", "1", "-o", png}, // no such station
        {"ladder", kMuting, "--unit", "0", "--network", "1"},             // no output
        {"ladder", kMuting, "--unit", "0", "--network", "1", "-o", dir.filePath("x.pdf")},
        {"ladder", kMuting, "--unit", "0", "--sequence", "1", "--network", "1", "-o", png},
        {"ladder", "--unit", "0", "--network", "1", "-o", png}, // no file
        {"ladder", dir.filePath("missing.sps"), "--unit", "0", "--network", "1", "-o", png},
        {"ladder", kMuting, "--unit", "0", "--network", "1", "-o", "/nonexistent-dir/x.png"},
        {"roundtrip"},
    };
    for (const auto& arguments : bad) {
        CliRun run = cli(arguments);
        EXPECT_EQ(run.exitCode, 2) << arguments.join(' ').toStdString();
        EXPECT_FALSE(run.err.isEmpty());
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
        CliRun run = cli(QStringList{"ladder", kMuting, "-o", png} + c.arguments);
        EXPECT_EQ(run.exitCode, 1) << c.message;
        EXPECT_TRUE(run.err.contains(c.message)) << run.err.toStdString();
    }
    const QString broken = writeTemp(dir, "bad.sps", "! pgm_pluto:00\nS0.0_0\nQ0.1 = \n");
    CliRun run = cli({"ladder", broken, "--unit", "0", "--network", "1", "-o", png});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.err.contains("bad.sps:3:"));
    EXPECT_FALSE(QFile::exists(png));
}

// The round trip through the ladder model prints exactly the canonical text,
// for every manual example and for a project with grouped networks.
TEST(RoundtripCli, PrintsTheCanonicalTextOfEveryManualExample) {
    for (const auto& path : rs::test::manualExamples()) {
        const QString file = QString::fromStdString(path.string());
        CliRun format = cli({"format", file});
        CliRun roundtrip = cli({"roundtrip", file});
        EXPECT_EQ(roundtrip.exitCode, 0) << path << roundtrip.err.toStdString();
        EXPECT_EQ(roundtrip.out, format.out) << path;
    }
    QTemporaryDir dir;
    const QString grouped = writeTemp(
        dir, "grouped.sps",
        "! pgm_pluto:00\nS0.0_0\nM0.3 = I0.3\n;@network comment=\"Both \\\"outputs\\\"\"\n"
        "Q0.2 = I0.1 * (I0.2 + M0.0)   ; A\nQ0.3 = I0.1 * (I0.2 + M0.0)   ; B\n; note\n\n"
        ";@network comment=\"\"\nM0.0\nQ0.17\n");
    CliRun format = cli({"format", grouped});
    CliRun roundtrip = cli({"roundtrip", grouped});
    EXPECT_EQ(roundtrip.exitCode, 0) << roundtrip.err.toStdString();
    EXPECT_EQ(roundtrip.out, format.out);
}

TEST(RoundtripCli, AProjectWithErrorsExits1) {
    QTemporaryDir dir;
    const QString broken = writeTemp(dir, "bad.sps", "! pgm_pluto:00\nS0.0_0\nQ0.1 = I0.1 +\n");
    CliRun run = cli({"roundtrip", broken});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.err.contains("bad.sps:3:"));
}

} // namespace
