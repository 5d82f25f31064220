// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProgramRun.h"
#include "QtPrinting.h"

#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

const QByteArray kBlocksUserLibrary = "rungsmith-library 1\n"
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
    const rs::test::ProgramRun run = rs::test::runCli({"blocks", "list"});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_EQ(run.errText(), "");
    EXPECT_TRUE(run.outText().contains("Rungsmith_Basics EquivalentInputs(Channel1, Channel2, "
                                       "[DiscrepancyTime] -> Out, [Fault])\n"))
        << run.outText().toStdString();
    EXPECT_TRUE(run.outText().contains("Rungsmith_Basics ResetLatch(Enable, Reset -> Out, "
                                       "[ResetLamp])\n"));
    const rs::test::ProgramRun only =
        rs::test::runCli({"blocks", "list", "--lib", "rungsmith_basics"});
    EXPECT_EQ(only.exitCode, 0);
    QString basics;
    for (const QString& line : run.outText().split('\n', Qt::SkipEmptyParts))
        if (line.startsWith(QStringLiteral("Rungsmith_Basics ")))
            basics += line + '\n';
    EXPECT_EQ(only.outText(), basics);
}

TEST(BlocksCli, AUserLibraryGivenAsAFileIsListedAndShown) {
    QTemporaryDir dir;
    const QString path = rs::test::writeFile(dir, "mine.rslib", kBlocksUserLibrary);
    const rs::test::ProgramRun list = rs::test::runCli({"blocks", "list", "--lib", path});
    EXPECT_EQ(list.exitCode, 0);
    EXPECT_EQ(list.outText(), "Mine Invert(In -> Out)\n");
    const rs::test::ProgramRun both =
        rs::test::runCli({"blocks", "list", "--lib", path, "--lib", "Rungsmith_Basics"});
    EXPECT_TRUE(both.outText().startsWith(list.outText())) << both.outText().toStdString();
    EXPECT_TRUE(both.outText().contains(QStringLiteral("\nRungsmith_Basics ResetLatch(")));
    EXPECT_FALSE(both.outText().contains(QStringLiteral("Rungsmith_System")));

    const rs::test::ProgramRun show =
        rs::test::runCli({"blocks", "show", "invert", "--lib", path, "--language", "de"});
    EXPECT_EQ(show.exitCode, 0);
    EXPECT_EQ(show.outText(), "Invert: macro block, version 1, library Mine 0.1\n"
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
    const rs::test::ProgramRun swedish =
        rs::test::runCli({"blocks", "show", "Invert", "--lib", path, "--language", "sv"});
    EXPECT_TRUE(swedish.outText().contains("\n  Out is the inverse of In.\n"));
}

TEST(BlocksCli, ShowsAStandardBlockInEnglishByDefault) {
    const rs::test::ProgramRun run = rs::test::runCli({"blocks", "show", "ResetLatch"});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_TRUE(run.outText().startsWith("ResetLatch: macro block, version 1.0, library "
                                         "Rungsmith_Basics 1.0\n\n  Latch with a reset button.\n"))
        << run.outText().toStdString();
    EXPECT_TRUE(
        run.outText().contains("  in  Enable               bit             primary   required"));
    EXPECT_TRUE(run.outText().contains("Private variables:\n  on memory\n"));
    EXPECT_TRUE(run.outText().contains("  {ResetLamp} = {Enable} * /{#on}\n"));
    const rs::test::ProgramRun swedish =
        rs::test::runCli({"blocks", "show", "ResetLatch", "--language", "sv"});
    EXPECT_TRUE(swedish.outText().contains("  Låsning med återställningsknapp.\n"));
}

TEST(BlocksCli, ShowsAStateMachinesStatesAndTransitionsInTheChosenLanguage) {
    const rs::test::ProgramRun run = rs::test::runCli({"blocks", "show", "SF_EmergencyStop"});
    EXPECT_EQ(run.exitCode, 0);
    const QString text = run.outText();
    EXPECT_TRUE(text.contains(QRegularExpression(
        "\n  16#8000  released and acknowledged: safe to run +Ready, S_EStopOut\n")))
        << text.toStdString();
    // 8003's list in the order it is tried, Activate off first.
    EXPECT_TRUE(text.contains(QRegularExpression("\n  any +/Activate +-> 16#0000\n")));
    EXPECT_TRUE(text.contains(QRegularExpression("\n  16#8003 +Reset \\* /resetEdge +-> 16#C001\n"
                                                 " +/S_EStopIn +-> 16#8002\n"
                                                 " +resetEdge +-> 16#8000\n")))
        << text.toStdString();
    const rs::test::ProgramRun german =
        rs::test::runCli({"blocks", "show", "SF_EmergencyStop", "--language", "de"});
    EXPECT_FALSE(german.outText().contains("released and acknowledged"));
    EXPECT_TRUE(german.outText().contains("\n  16#8000  ")) << german.outText().toStdString();
    const rs::test::ProgramRun latch = rs::test::runCli({"blocks", "show", "ResetLatch"});
    EXPECT_FALSE(latch.outText().contains("States")) << "a body without a state register";
}

TEST(BlocksCli, ABadLibraryIsReportedAtItsLineAndColumnWithExit1) {
    QTemporaryDir dir;
    QByteArray text = kBlocksUserLibrary;
    text.replace("{Out} = /{In}", "{Out} = /{Inn}");
    const QString path = rs::test::writeFile(dir, "bad.rslib", text);
    const rs::test::ProgramRun run = rs::test::runCli({"blocks", "list", "--lib", path});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.errText(), path + ":11:19: error: '{Inn}' names no pin of the block\n");
    EXPECT_EQ(run.outText(), "");
}

TEST(BlocksCli, UnknownBlockIsExit1AndUsageErrorsAreExit2) {
    const rs::test::ProgramRun unknown = rs::test::runCli({"blocks", "show", "NoSuchBlock"});
    EXPECT_EQ(unknown.exitCode, 1);
    EXPECT_EQ(unknown.errText(), "rungsmith-cli: no block named 'NoSuchBlock' in the libraries\n");

    EXPECT_EQ(rs::test::runCli({"blocks"}).exitCode, 2);
    EXPECT_EQ(rs::test::runCli({"blocks", "remove"}).exitCode, 2);
    EXPECT_EQ(rs::test::runCli({"blocks", "show"}).exitCode, 2);
    EXPECT_EQ(rs::test::runCli({"blocks", "list", "extra"}).exitCode, 2);
    const rs::test::ProgramRun language =
        rs::test::runCli({"blocks", "show", "ResetLatch", "--language", "fr"});
    EXPECT_EQ(language.exitCode, 2);
    EXPECT_TRUE(language.errText().contains("--language takes en, sv or de, not 'fr'"));
    const rs::test::ProgramRun noLibrary = rs::test::runCli({"blocks", "list", "--lib", "Nowhere"});
    EXPECT_EQ(noLibrary.exitCode, 2);
    EXPECT_EQ(noLibrary.errText(),
              "rungsmith-cli: --lib Nowhere: no library of that name and no such file\n");
    const rs::test::ProgramRun missing =
        rs::test::runCli({"blocks", "list", "--lib", "/nonexistent/x.rslib"});
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_TRUE(missing.errText().startsWith("rungsmith-cli: cannot read /nonexistent/x.rslib"));
}

TEST(BlocksCli, HelpListsTheVerbAndItsOptions) {
    const rs::test::ProgramRun run = rs::test::runCli({"--help"});
    EXPECT_TRUE(run.outText().contains("blocks list [--lib NAME|FILE]..."));
    EXPECT_TRUE(run.outText().contains("--language <LANG>"));
}
