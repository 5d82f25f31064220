// SPDX-License-Identifier: GPL-3.0-or-later
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

// Readable failure messages.
inline void PrintTo(const QString& text, std::ostream* os) {
    *os << text.toStdString();
}

namespace {

struct CliRun {
    int exitCode = -1;
    QString out;
    QString err;
};

CliRun cli(const QStringList& arguments) {
    QProcess process;
    process.start(QStringLiteral(RUNGSMITH_CLI), arguments);
    process.waitForFinished(30000);
    return {process.exitCode(), QString::fromUtf8(process.readAllStandardOutput()),
            QString::fromUtf8(process.readAllStandardError())};
}

QString writeTemp(QTemporaryDir& dir, const QString& name, const QByteArray& text) {
    QFile file(dir.filePath(name));
    file.open(QIODevice::WriteOnly);
    file.write(text);
    return file.fileName();
}

const QString kMuting = QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps");

} // namespace

TEST(Cli, CheckOfAGoodProjectSaysResultOk) {
    CliRun run = cli({"check", kMuting});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_EQ(run.out, "0 Error(s) detected Result=OK\n");
    // The manual's own example leaves the muting lamp Q0.17 without an I/O declaration.
    EXPECT_EQ(run.err, kMuting + ":37:1: warning: unconfigured I/O: Q0.17 has no I/O declaration "
                                 "in the code of unit 0\n");
    CliRun quiet = cli({"check", "--no-io-warnings", kMuting});
    EXPECT_EQ(quiet.exitCode, 0);
    EXPECT_EQ(quiet.err, "");
}

TEST(Cli, CheckReportsEveryErrorWithFileLineAndColumn) {
    QTemporaryDir dir;
    QString path = writeTemp(
        dir, "bad.sps", "! pgm_pluto:00\nS0.0_0\nQ0.1 = I0.0 +\nQ0.2 = Nothing\nQ0.3 = (I0.1\n");
    CliRun run = cli({"check", path});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.out, "3 Error(s) detected Result=FAILED\n");
    EXPECT_EQ(run.err, path + ":3:14: error: expected an operand after '+'\n" + path +
                           ":4:8: error: unknown name 'Nothing': declare it with '! "
                           "<address>=Nothing'\n" +
                           path + ":5:13: error: expected ')', found the end of the line\n");
}

TEST(Cli, FormatPrintsCanonicalTextAndIsIdempotent) {
    CliRun first = cli({"format", kMuting});
    ASSERT_EQ(first.exitCode, 0);
    EXPECT_TRUE(first.out.contains("Q0.2 = I0.12 * (I0.13 + M0.0) * (P(I0.14) * I0.2 + Q0.2)\n"));
    QTemporaryDir dir;
    QString path = writeTemp(dir, "formatted.sps", first.out.toUtf8());
    CliRun second = cli({"format", path});
    EXPECT_EQ(second.exitCode, 0);
    EXPECT_EQ(second.out, first.out);
}

TEST(Cli, FormatRefusesAProjectWithErrors) {
    QTemporaryDir dir;
    QString path = writeTemp(dir, "bad.sps", "! pgm_pluto:00\nS0.0_0\nQ0.1 = \n");
    CliRun run = cli({"format", path});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.out, "");
    EXPECT_TRUE(run.err.startsWith(path + ":3:")) << run.err.toStdString();
}

TEST(Cli, UnreadableFilesAndUsageErrorsExitWithTwo) {
    CliRun missing = cli({"check", "/nonexistent/x.sps"});
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_TRUE(missing.err.contains("cannot read /nonexistent/x.sps"))
        << missing.err.toStdString();
    EXPECT_EQ(cli({}).exitCode, 2);
    EXPECT_EQ(cli({"frobnicate", kMuting}).exitCode, 2);
    EXPECT_EQ(cli({"check"}).exitCode, 2);
    EXPECT_EQ(cli({"check", "--bogus", kMuting}).exitCode, 2);
}

TEST(Cli, CompileWritesTheImageBesideTheProjectOrWhereAsked) {
    QTemporaryDir dir;
    QFile::copy(kMuting, dir.filePath("muting.sps"));
    CliRun beside = cli({"compile", dir.filePath("muting.sps")});
    EXPECT_EQ(beside.exitCode, 0);
    EXPECT_EQ(beside.out, "0 Error(s) detected Result=OK\n");
    QFile image(dir.filePath("muting.hps"));
    ASSERT_TRUE(image.open(QIODevice::ReadOnly));
    const QByteArray hex = image.readAll();
    EXPECT_TRUE(hex.startsWith(":10000000525349"));
    EXPECT_TRUE(hex.endsWith(":00000001FF\n"));

    CliRun asked = cli({"compile", kMuting, "-o", dir.filePath("out.hps")});
    EXPECT_EQ(asked.exitCode, 0);
    QFile out(dir.filePath("out.hps"));
    ASSERT_TRUE(out.open(QIODevice::ReadOnly));
    EXPECT_EQ(out.readAll(), hex);
}

TEST(Cli, CompileWritesNothingWhenThereAreErrors) {
    QTemporaryDir dir;
    QString path = writeTemp(dir, "bad.sps",
                             "! id_pluto:00=000000000000\n! pgm_pluto:00\nS0.0_0\nJ(+1) = I0.0\n");
    CliRun run = cli({"compile", path});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.out, "1 Error(s) detected Result=FAILED\n");
    EXPECT_TRUE(run.err.startsWith(path + ":4:1: error: J(+1) in the PLC code"))
        << run.err.toStdString();
    EXPECT_FALSE(QFile::exists(dir.filePath("bad.hps")));
    CliRun unwritable = cli({"compile", kMuting, "-o", "/nonexistent/dir/x.hps"});
    EXPECT_EQ(unwritable.exitCode, 2);
    EXPECT_TRUE(unwritable.err.contains("cannot write /nonexistent/dir/x.hps"));
}

TEST(Cli, HelpAndVersion) {
    CliRun help = cli({"--help"});
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_TRUE(help.out.contains("check FILE.sps"));
    CliRun version = cli({"--version"});
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_TRUE(version.out.startsWith("rungsmith-cli "));
}
