// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProgramRun.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

// `protect` and the writing verbs on a protected project (cli.md, "Verbs for
// review, change control and project work"; the manual's Password protect,
// Part 1, 4.1), run on files in a temporary folder.

using rs::test::readFile;
using rs::test::runCli;
using rs::test::writeFile;

namespace {

const QByteArray kPress = "$name Press\n"
                          "! id_pluto:00=000000000000\n"
                          "! type_pluto:00=A20,is3\n"
                          "! pgm_pluto:00\n"
                          "S0.0_0\n"
                          ";@network comment=\"Door switch fitted\" option=\"on\"\n"
                          "S(M0.5)\n"
                          ";@network comment=\"Outputs\"\n"
                          "Q0.2 = I0.0 * M0.5\n"
                          "Q0.3 = I0.1\n";

const QByteArray kMain = "Kärnan 7 main password\n";

struct Protected {
    QString path;
    QString password;
};

Protected protectedPress(QTemporaryDir& dir) {
    const QString password = writeFile(dir, "main.txt", kMain);
    const QString out = dir.filePath("protected.sps");
    const auto run = runCli(
        {"protect", writeFile(dir, "press.sps", kPress), "-o", out, "--password-file", password});
    EXPECT_EQ(run.exitCode, 0) << run.err.toStdString();
    return {out, password};
}

TEST(ProtectCli, TheFileKeepsNoPasswordAndReadsEverywhereWithout) {
    QTemporaryDir dir;
    const Protected press = protectedPress(dir);
    const QByteArray text = readFile(press.path);
    EXPECT_TRUE(text.contains(";@protected options=\"main\"")) << text.toStdString();
    EXPECT_FALSE(text.contains("main password"));
    EXPECT_FALSE(text.contains(QByteArray("Kärnan")));
    for (const char* verb : {"check", "compile", "format", "signature"})
        EXPECT_EQ(runCli({verb, press.path}).exitCode, 0) << verb;
    EXPECT_EQ(runCli({"format", press.path}).out, text);
}

TEST(ProtectCli, WritingVerbsRefuseWithoutThePasswordAndWriteWithIt) {
    QTemporaryDir dir;
    const Protected press = protectedPress(dir);
    const QString csv =
        writeFile(dir, "names.csv", "Variable;Symbolic Name;Description\nI0.0;Start;\n");
    const QString wrong = writeFile(dir, "wrong.txt", "not it\n");
    const QString out = dir.filePath("out.sps");
    const QList<QStringList> writers = {
        {"vars", "import", press.path, csv, "-o", out},
        {"validate", press.path, "--by", "Eva", "-o", out},
        {"merge", press.path, writeFile(dir, "empty.sps", "$name Other\n"), "-o", out},
        {"protect", press.path, "-o", out, "--password-file", wrong},
        {"protect", press.path, "-o", out, "--password-file", wrong, "--remove"},
    };
    for (const QStringList& writer : writers) {
        QStringList refused = writer;
        if (!refused.contains("--password-file"))
            refused << "--password-file" << wrong;
        for (const QStringList& arguments : {writer, refused}) {
            const auto run = runCli(arguments);
            EXPECT_EQ(run.exitCode, 1) << arguments.join(' ').toStdString();
            EXPECT_TRUE(run.err.contains("password")) << run.err.toStdString();
            EXPECT_FALSE(QFile::exists(out)) << arguments.join(' ').toStdString();
        }
        if (writer.contains("--password-file"))
            continue;
        const auto allowed = runCli(QStringList(writer) << "--password-file" << press.password);
        EXPECT_EQ(allowed.exitCode, 0) << allowed.err.toStdString();
        // What it wrote is sealed again: it reads without a complaint.
        const auto check = runCli({"check", out});
        EXPECT_EQ(check.exitCode, 0) << writer.join(' ').toStdString() << check.err.toStdString();
        QFile::remove(out);
    }
}

TEST(ProtectCli, AChangeMadeByHandIsAnErrorAtItsLine) {
    QTemporaryDir dir;
    const Protected press = protectedPress(dir);
    QByteArray text = readFile(press.path);
    text.replace("Q0.3 = I0.1", "Q0.3 = I0.2");
    const QString edited = writeFile(dir, "edited.sps", text);
    const int line = 1 + text.left(text.indexOf("Q0.3 = I0.2")).count('\n');
    for (const char* verb : {"check", "compile"}) {
        const auto run = runCli({verb, edited});
        EXPECT_EQ(run.exitCode, 1);
        EXPECT_TRUE(run.errText().startsWith(
            QStringLiteral("%1:%2:1: error: changed outside Rungsmith").arg(edited).arg(line)))
            << run.err.toStdString();
    }
}

TEST(ProtectCli, OwnOptionsPasswordAndRemoval) {
    QTemporaryDir dir;
    const QString main = writeFile(dir, "main.txt", kMain);
    const QString options = writeFile(dir, "options.txt", "options 12\n");
    const QString in = writeFile(dir, "press.sps", kPress);
    const QString out = dir.filePath("protected.sps");
    EXPECT_EQ(
        runCli({"protect", in, "-o", out, "--password-file", main, "--options", "own"}).exitCode,
        2);
    EXPECT_EQ(runCli({"protect", in, "-o", out, "--password-file", main, "--options-password-file",
                      options})
                  .exitCode,
              2);
    const auto own = runCli({"protect", in, "-o", out, "--password-file", main, "--options", "own",
                             "--options-password-file", options});
    ASSERT_EQ(own.exitCode, 0) << own.err.toStdString();
    EXPECT_TRUE(readFile(out).contains("options=\"own\""));
    EXPECT_FALSE(readFile(out).contains("options 12"));
    // The options' password is not the main one.
    const QString plain = dir.filePath("plain.sps");
    EXPECT_EQ(
        runCli({"protect", out, "-o", plain, "--password-file", options, "--remove"}).exitCode, 1);
    const auto removed = runCli({"protect", out, "-o", plain, "--password-file", main, "--remove"});
    ASSERT_EQ(removed.exitCode, 0) << removed.err.toStdString();
    EXPECT_EQ(readFile(plain), kPress);
}

} // namespace

namespace {

// A change made by hand (a merge, say) is refused until the password's holder
// accepts it; then the file reads cleanly again.
TEST(ProtectCli, AHandChangeIsAcceptedOnlyWithTheMainPasswordAndTheFlag) {
    QTemporaryDir dir;
    const Protected press = protectedPress(dir);
    QByteArray text = readFile(press.path);
    text.replace("Q0.3 = I0.1", "Q0.3 = I0.1 * I0.4");
    const QString edited = writeFile(dir, "edited.sps", text);
    const QString out = dir.filePath("accepted.sps");
    EXPECT_EQ(runCli({"protect", edited, "-o", out, "--password-file", press.password}).exitCode,
              1);
    EXPECT_FALSE(QFile::exists(out));
    const QString wrong = writeFile(dir, "wrong.txt", "not it\n");
    EXPECT_EQ(runCli({"protect", edited, "-o", out, "--password-file", wrong, "--accept-changes"})
                  .exitCode,
              1);
    EXPECT_FALSE(QFile::exists(out));
    const auto accepted = runCli(
        {"protect", edited, "-o", out, "--password-file", press.password, "--accept-changes"});
    ASSERT_EQ(accepted.exitCode, 0) << accepted.errText().toStdString();
    EXPECT_EQ(runCli({"check", out}).exitCode, 0);
    EXPECT_TRUE(readFile(out).contains("Q0.3 = I0.1 * I0.4"));
}

} // namespace
