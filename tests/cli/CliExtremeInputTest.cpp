// SPDX-License-Identifier: GPL-3.0-or-later
// Extreme and malformed project text on the command line: every verb answers
// with a message and an exit code of the contract, never a crash.

#include "ProgramRun.h"
#include "QtPrinting.h"
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

const QByteArray kHead = "! id_pluto:00=000000000000\n! pgm_pluto:00\nS0.0_0\n";

// I0.0 + I0.1 + ... with `count` operands, cycling through the A20's inputs.
QByteArray chain(int count, char op) {
    QByteArray text;
    text.reserve(count * 6);
    for (int i = 0; i < count; ++i) {
        if (i)
            text += op;
        text += "I0." + QByteArray::number(i % 8);
    }
    return text;
}

} // namespace

TEST(CliExtremeInput, DeeplyNestedParenthesesAreAnErrorInEveryVerb) {
    QTemporaryDir dir;
    const QString path = rs::test::writeFile(dir, "nested.sps",
                                             kHead + "Q0.0 = " + QByteArray(10000, '(') + "I0.0" +
                                                 QByteArray(10000, ')') + "\n");
    // "Q0.0 = " takes columns 1-7; the 101st parenthesis is at column 108.
    const QString message = path + ":4:108: error: expression nested deeper than 100 levels\n";
    for (const char* verb : {"check", "compile", "format"}) {
        const rs::test::ProgramRun run =
            rs::test::runCli({verb, path, "-o", dir.filePath("nested.hps")});
        ASSERT_FALSE(run.crashed) << verb;
        EXPECT_EQ(run.exitCode, 1) << verb;
        EXPECT_TRUE(run.errText().startsWith(message))
            << verb << ": " << run.errText().left(300).toStdString();
    }
    EXPECT_FALSE(QFile::exists(dir.filePath("nested.hps")));
}

TEST(CliExtremeInput, TheDeepestNestingAllowedPassesEveryVerb) {
    // Each level adds an OR and an AND: the deepest tree 100 parentheses can make.
    QByteArray condition = "I0.0";
    for (int level = 0; level < 100; ++level)
        condition = "I0.1 + I0.2 * (" + condition + ")";
    QTemporaryDir dir;
    const QString path = rs::test::writeFile(dir, "deep.sps", kHead + "Q0.0 = " + condition + "\n");
    for (const QStringList& arguments :
         {QStringList{"check", path}, QStringList{"compile", path, "-o", dir.filePath("deep.hps")},
          QStringList{"format", path}, QStringList{"roundtrip", path},
          QStringList{"ladder", path, "--unit", "0", "--network", "1", "-o",
                      dir.filePath("deep.svg")}}) {
        const rs::test::ProgramRun run = rs::test::runCli(arguments);
        ASSERT_FALSE(run.crashed) << arguments.front().toStdString();
        EXPECT_EQ(run.exitCode, 0)
            << arguments.front().toStdString() << ": " << run.errText().left(300).toStdString();
    }
    EXPECT_EQ(rs::test::runCli({"roundtrip", path}).outText(),
              rs::test::runCli({"format", path}).outText());
}

TEST(CliExtremeInput, ALongFlatChainIsReadCheckedAndCompiled) {
    QTemporaryDir dir;
    for (char op : {'+', '*'}) {
        const QString path =
            rs::test::writeFile(dir, "chain.sps", kHead + "Q0.0 = " + chain(100000, op) + "\n");
        const rs::test::ProgramRun format = rs::test::runCli({"format", path});
        ASSERT_FALSE(format.crashed);
        EXPECT_EQ(format.exitCode, 0);
        EXPECT_EQ(format.outText().size(),
                  rs::test::readFile(path).size() + 2 * 99999); // spaces around each op
        for (const char* verb : {"check", "compile"}) {
            const rs::test::ProgramRun run = rs::test::runCli({verb, "--no-io-warnings", path});
            ASSERT_FALSE(run.crashed) << verb;
            EXPECT_EQ(run.exitCode, 0) << verb << run.errText().left(300).toStdString();
        }
    }
}

TEST(CliExtremeInput, AProgramLargerThanItsUnitsMemoryIsAnErrorAtItsPgmPlutoLine) {
    // Unit 0's image would run into unit 1's: this aborted with an uncaught exception.
    QByteArray text = "! id_pluto:00=000000000000\n! id_pluto:01=000000000000\n"
                      "! pgm_pluto:00\nS0.0_0\n";
    // 15,000 series of 40 contacts: 1,176 bytes of image each, 17.6 MB in all.
    QByteArray series = "I0.0";
    for (int i = 1; i < 40; ++i)
        series += " * I0." + QByteArray::number(i % 8);
    for (int i = 0; i < 15000; ++i)
        text += "M0." + QByteArray::number(i % 16) + " = " + series + "\n";
    text += "! pgm_pluto:01\nS1.0_0\nQ1.0 = I1.0\n";
    QTemporaryDir dir;
    const QString path = rs::test::writeFile(dir, "large.sps", text);
    const QString output = dir.filePath("large.hps");
    const rs::test::ProgramRun run =
        rs::test::runCli({"compile", "--no-io-warnings", path, "-o", output});
    ASSERT_FALSE(run.crashed);
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_TRUE(run.errText().startsWith(path + ":3:1: error: program of unit 0 is "))
        << run.errText().left(300).toStdString();
    EXPECT_TRUE(run.errText().contains("bytes; a Pluto A20 holds at most 16777216 bytes"));
    EXPECT_FALSE(run.errText().contains("internal error"));
    EXPECT_FALSE(QFile::exists(output));
}

TEST(CliExtremeInput, CarriageReturnAloneEndsALine) {
    const QByteArray lf = "$name Lines\n! id_pluto:00=000000000000\n! pgm_pluto:00\n"
                          "! I0.0=Start\nS0.0_0\n; the lamp\nQ0.0 = Start ; on\n\nM0.1 = I0.1\n";
    QByteArray cr = lf;
    cr.replace('\n', '\r');
    QTemporaryDir dir;
    const QString lfPath = rs::test::writeFile(dir, "lf.sps", lf);
    const QString crPath = rs::test::writeFile(dir, "cr.sps", cr);
    const rs::test::ProgramRun lfCompile =
        rs::test::runCli({"compile", lfPath, "-o", dir.filePath("lf.hps")});
    const rs::test::ProgramRun crCompile =
        rs::test::runCli({"compile", crPath, "-o", dir.filePath("cr.hps")});
    ASSERT_EQ(lfCompile.exitCode, 0) << lfCompile.errText().toStdString();
    EXPECT_EQ(crCompile.exitCode, 0) << crCompile.errText().toStdString();
    EXPECT_EQ(crCompile.errText(), QString(lfCompile.errText()).replace(lfPath, crPath));
    EXPECT_EQ(rs::test::readFile(dir.filePath("cr.hps")),
              rs::test::readFile(dir.filePath("lf.hps")));
    const rs::test::ProgramRun crFormat = rs::test::runCli({"format", crPath});
    EXPECT_EQ(crFormat.exitCode, 0);
    EXPECT_EQ(crFormat.outText(), rs::test::runCli({"format", lfPath}).outText());
    EXPECT_FALSE(crFormat.outText().contains('\r'));
}

TEST(CliExtremeInput, ControlCharactersInMessagesAreShownNotCut) {
    QTemporaryDir dir;
    const QString path = rs::test::writeFile(
        dir, "nul.sps", kHead + "Q0.0 = I0.0 " + QByteArray("\0\x01 zz", 5) + "\n");
    const rs::test::ProgramRun run = rs::test::runCli({"check", "--no-io-warnings", path});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_EQ(run.errText(), path + ":4:13: error: unexpected '\\0' after the statement\n");
}

TEST(CliExtremeInput, ReadingAUnitOfAnotherProjectIsAWarningAndSimulates) {
    QTemporaryDir dir;
    const QString path = rs::test::writeFile(dir, "other.sps", kHead + "Q0.0 = I1.0 * GM1.2\n");
    const rs::test::ProgramRun check = rs::test::runCli({"check", "--no-io-warnings", path});
    EXPECT_EQ(check.exitCode, 0);
    // Once for the unit, at its first use.
    EXPECT_EQ(check.errText(), path +
                                   ":4:8: warning: unit 1 is not in this project; its globals come "
                                   "from another project on the bus\n");
    const rs::test::ProgramRun compile = rs::test::runCli({"compile", "--no-io-warnings", path});
    EXPECT_EQ(compile.exitCode, 0) << compile.errText().toStdString();
    const QString scenario = rs::test::writeFile(dir, "other.scn",
                                                 "scans 1\nexpect Q0.0 0\nset I1.0 1\nset GM1.2 1\n"
                                                 "scans 1\nexpect Q0.0 1\nset I1.0 0\nscans 1\n"
                                                 "expect Q0.0 0\n");
    const rs::test::ProgramRun test =
        rs::test::runCli({"test", "--no-io-warnings", path, scenario});
    EXPECT_EQ(test.exitCode, 0) << (test.outText() + test.errText()).toStdString();
    EXPECT_TRUE(test.outText().contains("3 passed, 0 failed")) << test.outText().toStdString();
}

TEST(CliExtremeInput, WritingOrReadingLocalsOfAUnitOutsideTheProjectStaysAnError) {
    QTemporaryDir dir;
    const QString path =
        rs::test::writeFile(dir, "other.sps", kHead + "Q0.0 = M1.0\nS(GM1.0) = I0.0\n");
    const rs::test::ProgramRun check = rs::test::runCli({"check", "--no-io-warnings", path});
    EXPECT_EQ(check.exitCode, 1);
    EXPECT_TRUE(check.errText().contains(path + ":4:8: error:")) << check.errText().toStdString();
    EXPECT_TRUE(check.errText().contains(path + ":5:3: error:")) << check.errText().toStdString();
}

TEST(CliExtremeInput, TwoRunsCompileTheSameBytes) {
    const QString muting = QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps");
    QTemporaryDir dir;
    ASSERT_EQ(rs::test::runCli({"compile", muting, "-o", dir.filePath("a.hps")}).exitCode, 0);
    ASSERT_EQ(rs::test::runCli({"compile", muting, "-o", dir.filePath("b.hps")}).exitCode, 0);
    const QByteArray first = rs::test::readFile(dir.filePath("a.hps"));
    EXPECT_FALSE(first.isEmpty());
    EXPECT_EQ(first, rs::test::readFile(dir.filePath("b.hps")));
}
