// SPDX-License-Identifier: GPL-3.0-or-later
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

// The standard libraries are found beside the binary, as in any build tree.
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

const QByteArray kUserLibrary = "rungsmith-library 1\n"
                                "library Mine\n"
                                "version 0.1\n"
                                "block Invert\n"
                                "    kind macro\n"
                                "    version 1\n"
                                "    description en Out is the inverse of In.\n"
                                "    description de Out ist die Umkehrung von In.\n"
                                "    pin In in bit primary default=0\n"
                                "    pin Out out bit primary\n"
                                "    body {Out} = /{In}\n";

} // namespace

TEST(BlocksCli, ListsTheStandardLibraryOneLinePerBlock) {
    const CliRun run = cli({"blocks", "list"});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_EQ(run.err, "");
    EXPECT_TRUE(run.out.contains("Rungsmith_Basics EquivalentInputs(Channel1, Channel2, "
                                 "[DiscrepancyTime] -> Out, [Fault])\n"))
        << run.out.toStdString();
    EXPECT_TRUE(run.out.contains("Rungsmith_Basics ResetLatch(Enable, Reset -> Out, "
                                 "[ResetLamp])\n"));
    const CliRun only = cli({"blocks", "list", "--lib", "rungsmith_basics"});
    EXPECT_EQ(only.exitCode, 0);
    EXPECT_EQ(only.out, run.out.section('\n', 0, 1) + "\n");
}

TEST(BlocksCli, AUserLibraryGivenAsAFileIsListedAndShown) {
    QTemporaryDir dir;
    const QString path = writeTemp(dir, "mine.rslib", kUserLibrary);
    const CliRun list = cli({"blocks", "list", "--lib", path});
    EXPECT_EQ(list.exitCode, 0);
    EXPECT_EQ(list.out, "Mine Invert(In -> Out)\n");
    const CliRun both = cli({"blocks", "list", "--lib", path, "--lib", "Rungsmith_Basics"});
    EXPECT_EQ(both.out.count('\n'), 3);

    const CliRun show = cli({"blocks", "show", "invert", "--lib", path, "--language", "de"});
    EXPECT_EQ(show.exitCode, 0);
    EXPECT_EQ(show.out, "Invert: macro block, version 1, library Mine 0.1\n"
                        "\n"
                        "  Out ist die Umkehrung von In.\n"
                        "\n"
                        "Pins:\n"
                        "  in  In                   bit             primary   default 0      "
                        "input,output,memory,global-memory,system-memory,register-bit\n"
                        "  out Out                  bit             primary   -              "
                        "output,memory,global-memory,system-memory,register-bit\n"
                        "\n"
                        "Timers: 0\n"
                        "\n"
                        "Body:\n"
                        "  {Out} = /{In}\n");
    // No Swedish text: English instead.
    const CliRun swedish = cli({"blocks", "show", "Invert", "--lib", path, "--language", "sv"});
    EXPECT_TRUE(swedish.out.contains("\n  Out is the inverse of In.\n"));
}

TEST(BlocksCli, ShowsAStandardBlockInEnglishByDefault) {
    const CliRun run = cli({"blocks", "show", "ResetLatch"});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_TRUE(run.out.startsWith("ResetLatch: macro block, version 1.0, library "
                                   "Rungsmith_Basics 1.0\n\n  Latch with a reset button.\n"))
        << run.out.toStdString();
    EXPECT_TRUE(run.out.contains("  in  Enable               bit             primary   required"));
    EXPECT_TRUE(run.out.contains("Private variables:\n  on memory\n"));
    EXPECT_TRUE(run.out.contains("  {ResetLamp} = {Enable} * /{#on}\n"));
    const CliRun swedish = cli({"blocks", "show", "ResetLatch", "--language", "sv"});
    EXPECT_TRUE(swedish.out.contains("  Låsning med återställningsknapp.\n"));
}

TEST(BlocksCli, ABadLibraryIsReportedAtItsLineAndColumnWithExit1) {
    QTemporaryDir dir;
    QByteArray text = kUserLibrary;
    text.replace("{Out} = /{In}", "{Out} = /{Inn}");
    const QString path = writeTemp(dir, "bad.rslib", text);
    const CliRun run = cli({"blocks", "list", "--lib", path});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.err, path + ":11:19: error: '{Inn}' names no pin of the block\n");
    EXPECT_EQ(run.out, "");
}

TEST(BlocksCli, UnknownBlockIsExit1AndUsageErrorsAreExit2) {
    const CliRun unknown = cli({"blocks", "show", "NoSuchBlock"});
    EXPECT_EQ(unknown.exitCode, 1);
    EXPECT_EQ(unknown.err, "rungsmith-cli: no block named 'NoSuchBlock' in the libraries\n");

    EXPECT_EQ(cli({"blocks"}).exitCode, 2);
    EXPECT_EQ(cli({"blocks", "remove"}).exitCode, 2);
    EXPECT_EQ(cli({"blocks", "show"}).exitCode, 2);
    EXPECT_EQ(cli({"blocks", "list", "extra"}).exitCode, 2);
    const CliRun language = cli({"blocks", "show", "ResetLatch", "--language", "fr"});
    EXPECT_EQ(language.exitCode, 2);
    EXPECT_TRUE(language.err.contains("--language takes en, sv or de, not 'fr'"));
    const CliRun noLibrary = cli({"blocks", "list", "--lib", "Nowhere"});
    EXPECT_EQ(noLibrary.exitCode, 2);
    EXPECT_EQ(noLibrary.err,
              "rungsmith-cli: --lib Nowhere: no library of that name and no such file\n");
    const CliRun missing = cli({"blocks", "list", "--lib", "/nonexistent/x.rslib"});
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_TRUE(missing.err.startsWith("rungsmith-cli: cannot read /nonexistent/x.rslib"));
}

TEST(BlocksCli, HelpListsTheVerbAndItsOptions) {
    const CliRun run = cli({"--help"});
    EXPECT_TRUE(run.out.contains("blocks list [--lib NAME|FILE]..."));
    EXPECT_TRUE(run.out.contains("--language <LANG>"));
}
