// SPDX-License-Identifier: GPL-3.0-or-later
#include "FullFileSystem.h"

#include "ProgramRun.h"
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

// Every verb that writes a file: on a full disk it fails with exit 2 and a
// message naming the file, and the file it would replace stays as it was.
// Every verb that reads: an endless or foreign-encoded input is refused.

using rs::test::FullFileSystem;

namespace {

const QString kOutputMuting = QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps");
const QByteArray kOld = "the validated version\n";

const QByteArray kOutputProject = "! id_pluto:00=000000000000\n"
                                  "! I0.0=Start\n"
                                  "! pgm_pluto:00\n"
                                  "S0.0_0\n"
                                  "Q0.2 = Start\n";

// Runs a writing verb against FILE on a full disk that already holds an old
// FILE, and checks the verb's failure and the old bytes.
void expectOldFileKept(const QString& name,
                       const std::function<QStringList(const QString&)>& arguments) {
    FullFileSystem disk;
    if (!disk.available())
        GTEST_SKIP() << disk.reason().toStdString();
    ASSERT_TRUE(disk.put(name, kOld));
    ASSERT_TRUE(disk.fill());
    const QString target = disk.filePath(name);
    const rs::test::ProgramRun run = rs::test::runCli(arguments(target));
    EXPECT_EQ(run.exitCode, 2) << run.errText().toStdString();
    EXPECT_TRUE(run.errText().contains("rungsmith-cli: cannot write " + target + ": "))
        << run.errText().toStdString();
    EXPECT_EQ(rs::test::readFile(target), kOld);
}

} // namespace

TEST(FileOutputCli, CompileToAFullDiskKeepsTheOldImage) {
    expectOldFileKept("image.hps", [](const QString& target) {
        return QStringList{"compile", kOutputMuting, "-o", target};
    });
}

TEST(FileOutputCli, VarsImportToAFullDiskKeepsTheOldProject) {
    QTemporaryDir dir;
    const QString project = rs::test::writeFile(dir, "p.sps", kOutputProject);
    const QString csv =
        rs::test::writeFile(dir, "in.csv", "Variable,Symbolic Name,Description\nI0.0,Go,\n");
    expectOldFileKept("out.sps", [&](const QString& target) {
        return QStringList{"vars", "import", project, csv, "-o", target};
    });
}

TEST(FileOutputCli, VarsExportToAFullDiskKeepsTheOldCsv) {
    expectOldFileKept("vars.csv", [](const QString& target) {
        return QStringList{"vars", "export", kOutputMuting, "-o", target};
    });
}

TEST(FileOutputCli, TestTraceToAFullDiskKeepsTheOldTrace) {
    QTemporaryDir dir;
    const QString project = rs::test::writeFile(dir, "p.sps", kOutputProject);
    const QString scenario =
        rs::test::writeFile(dir, "s.scn", "set I0.0 1\nscans 1\nexpect Q0.2 1\n");
    expectOldFileKept("run.vcd", [&](const QString& target) {
        return QStringList{"test", project, scenario, "--vcd", target};
    });
}

TEST(FileOutputCli, LadderPictureToAFullDiskKeepsTheOldPicture) {
    for (const char* name : {"network.svg", "network.png"})
        expectOldFileKept(name, [](const QString& target) {
            return QStringList{"ladder",    kOutputMuting, "--unit", "0",
                               "--network", "1",           "-o",     target};
        });
}

TEST(FileOutputCli, StandardOutputThatCannotBeWrittenIsAnError) {
    for (const QStringList& arguments :
         {QStringList{"format", kOutputMuting}, QStringList{"roundtrip", kOutputMuting}}) {
        const rs::test::ProgramRun run = rs::test::runCli(arguments, {QStringLiteral("/dev/full")});
        EXPECT_EQ(run.exitCode, 2) << arguments.join(' ').toStdString();
        EXPECT_EQ(run.errText(),
                  "rungsmith-cli: cannot write the standard output: No space left on device\n");
    }
}

TEST(FileOutputCli, EndlessInputsAreRefusedWithTheLimit) {
    QTemporaryDir dir;
    const QString project = rs::test::writeFile(dir, "p.sps", kOutputProject);
    const QString limit = ": larger than 64 MB, the most Rungsmith reads from one file\n";
    const std::pair<QStringList, QString> cases[] = {
        {{"check", "/dev/zero"}, "/dev/zero"},
        {{"vars", "import", project, "/dev/zero", "-o", dir.filePath("out.sps")}, "/dev/zero"},
        {{"test", project, "/dev/zero"}, "/dev/zero"},
    };
    for (const auto& [arguments, file] : cases) {
        const rs::test::ProgramRun run = rs::test::runCli(arguments);
        EXPECT_EQ(run.exitCode, 2) << arguments.join(' ').toStdString();
        EXPECT_EQ(run.errText(), "rungsmith-cli: " + file + limit);
    }
    EXPECT_FALSE(QFile::exists(dir.filePath("out.sps")));
}

TEST(FileOutputCli, Utf16ProjectsAreRefusedAndAByteOrderMarkIsAccepted) {
    QTemporaryDir dir;
    const QString wide = rs::test::writeFile(dir, "wide.sps", QByteArray("\xFF\xFE!\0 \0", 6));
    const rs::test::ProgramRun refused = rs::test::runCli({"check", wide});
    EXPECT_EQ(refused.exitCode, 2);
    EXPECT_EQ(refused.errText(),
              "rungsmith-cli: " + wide + ": UTF-16 text is not supported; save it as UTF-8\n");
    const QString marked = rs::test::writeFile(dir, "marked.sps", "\xEF\xBB\xBF" + kOutputProject);
    const rs::test::ProgramRun accepted = rs::test::runCli({"check", marked});
    EXPECT_EQ(accepted.exitCode, 0) << accepted.errText().toStdString();
    EXPECT_EQ(accepted.outText(), "0 Error(s) detected Result=OK\n");
}
