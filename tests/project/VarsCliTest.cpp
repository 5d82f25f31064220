// SPDX-License-Identifier: GPL-3.0-or-later
#include <QFile>
#include <QProcess>
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
    EXPECT_TRUE(process.waitForFinished(30000));
    return {process.exitCode(), process.readAllStandardOutput(),
            QString::fromUtf8(process.readAllStandardError())};
}

QByteArray readAll(const QString& path) {
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << path.toStdString();
    return file.readAll();
}

QString write(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes) {
    QFile file(dir.filePath(name));
    EXPECT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(bytes);
    return file.fileName();
}

const QString kMuting = QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps");

const QByteArray kProject = "$name Vars\n"
                            "! id_pluto:00=000000000000\n"
                            "! I0.0=MuteSensor1\n"
                            "! pgm_pluto:00\n"
                            "S0.0_0\n"
                            "Q0.2 = MuteSensor1\n";

} // namespace

TEST(VarsCli, ExportWritesTheCsv) {
    QTemporaryDir dir;
    const QString project = write(dir, "p.sps", kProject);
    const CliRun run = cli({"vars", "export", project, "-o", dir.filePath("out.csv")});
    EXPECT_EQ(run.exitCode, 0) << run.err.toStdString();
    EXPECT_EQ(readAll(dir.filePath("out.csv")),
              "\xEF\xBB\xBFVariable,Symbolic Name,Description\r\nI0.0,MuteSensor1,\r\n");
}

TEST(VarsCli, ImportWritesTheProjectWithTheNewNames) {
    QTemporaryDir dir;
    const QString project = write(dir, "p.sps", kProject);
    const QString csv = write(dir, "in.csv",
                              "Variable;Symbolic Name;Description\n"
                              "I0.0;Sensor1;left sensor\n");
    const QString out = dir.filePath("out.sps");
    const CliRun run = cli({"vars", "import", project, csv, "-o", out});
    EXPECT_EQ(run.exitCode, 0) << run.err.toStdString();
    EXPECT_EQ(readAll(out), "$name Vars\n"
                            "! id_pluto:00=000000000000\n"
                            ";@var I0.0 description=\"left sensor\"\n"
                            "! I0.0=Sensor1\n"
                            "! pgm_pluto:00\n"
                            "S0.0_0\n"
                            "Q0.2 = Sensor1\n");
}

TEST(VarsCli, BadRowsAreErrorsByLineAndNothingIsWritten) {
    QTemporaryDir dir;
    const QString project = write(dir, "p.sps", kProject);
    const QString csv = write(dir, "in.csv", "Variable,Symbolic Name\nI0.0,ok\nI0.1,9lives\n");
    const QString out = dir.filePath("out.sps");
    const CliRun run = cli({"vars", "import", project, csv, "-o", out});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.err.startsWith(csv + ":3:6: error: ")) << run.err.toStdString();
    EXPECT_FALSE(QFile::exists(out));
}

TEST(VarsCli, ExportImportRoundTripOfTheManualsExample) {
    QTemporaryDir dir;
    const QString csv = dir.filePath("muting.csv");
    ASSERT_EQ(cli({"vars", "export", kMuting, "-o", csv}).exitCode, 0);
    const QString out = dir.filePath("muting.sps");
    const CliRun run = cli({"vars", "import", kMuting, csv, "-o", out});
    EXPECT_EQ(run.exitCode, 0) << run.err.toStdString();
    const CliRun formatted = cli({"format", kMuting});
    EXPECT_EQ(readAll(out), formatted.out);
}

TEST(VarsCli, UsageAndUnreadableFilesAreExitTwo) {
    QTemporaryDir dir;
    EXPECT_EQ(cli({"vars"}).exitCode, 2);
    EXPECT_EQ(cli({"vars", "export", kMuting}).exitCode, 2); // no -o
    EXPECT_EQ(cli({"vars", "frobnicate", kMuting, "-o", dir.filePath("x")}).exitCode, 2);
    const CliRun missing =
        cli({"vars", "export", dir.filePath("none.sps"), "-o", dir.filePath("x.csv")});
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_TRUE(missing.err.contains("none.sps"));
    const CliRun unwritable = cli({"vars", "export", kMuting, "-o", dir.filePath("no/x.csv")});
    EXPECT_EQ(unwritable.exitCode, 2);
}
