// SPDX-License-Identifier: GPL-3.0-or-later
// rungsmith-cli links no QtGui: the verbs that draw load it with the module
// rungsmith-drawing.so (app/cli/Drawing.h), and the others do not pay for it
// (issue 23: 6 MB and 8 ms of every command).
#include "ProgramRun.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cstdlib>

namespace {

using rs::test::runCli;
using rs::test::runProgram;

const QString kMuting = QStringLiteral(RUNGSMITH_EXAMPLES "/muting.sps");

// The run with the dynamic loader saying which files it opens.
rs::test::ProgramRun runSayingWhatIsLoaded(const QString& program, const QStringList& arguments) {
    setenv("LD_DEBUG", "files", 1);
    auto run = runProgram(program, arguments);
    unsetenv("LD_DEBUG");
    return run;
}

} // namespace

TEST(DrawingModuleCli, OnlyTheVerbsThatDrawLoadQtGui) {
    QTemporaryDir dir;
    const auto check = runSayingWhatIsLoaded(RUNGSMITH_CLI, {"check", kMuting});
    ASSERT_EQ(check.exitCode, 0) << check.errText().toStdString();
    EXPECT_TRUE(check.err.contains("libQt6Core")) << "the loader said what it loads";
    EXPECT_FALSE(check.err.contains("libQt6Gui"));
    EXPECT_FALSE(check.err.contains("rungsmith-drawing"));

    const auto ladder =
        runSayingWhatIsLoaded(RUNGSMITH_CLI, {"ladder", kMuting, "--unit", "0", "--network", "1",
                                              "-o", dir.filePath("n.svg")});
    ASSERT_EQ(ladder.exitCode, 0) << ladder.errText().toStdString();
    EXPECT_TRUE(ladder.err.contains("rungsmith-drawing.so"));
    EXPECT_TRUE(ladder.err.contains("libQt6Gui"));
    EXPECT_TRUE(rs::test::readFile(dir.filePath("n.svg")).contains("<svg"));
}

// A program whose module is missing still does everything but draw, and says
// where it looked; it writes nothing.
TEST(DrawingModuleCli, WithoutTheModuleDrawingSaysWhereItLooked) {
    QTemporaryDir dir;
    const QString program = dir.filePath("rungsmith-cli");
    ASSERT_TRUE(QFile::copy(RUNGSMITH_CLI, program));
    const auto check = runProgram(program, {"check", kMuting});
    EXPECT_EQ(check.exitCode, 0) << check.errText().toStdString();

    const QString picture = dir.filePath("n.png");
    const auto ladder =
        runProgram(program, {"ladder", kMuting, "--unit", "0", "--network", "1", "-o", picture});
    EXPECT_EQ(ladder.exitCode, 2);
    EXPECT_TRUE(ladder.errText().startsWith("rungsmith-cli: drawing needs rungsmith-drawing.so"))
        << ladder.errText().toStdString();
    EXPECT_TRUE(ladder.errText().contains("../libexec/rungsmith"))
        << ladder.errText().toStdString();
    EXPECT_FALSE(QFile::exists(picture));

    const auto diff =
        runProgram(program, {"diff", kMuting, kMuting, "--pdf", dir.filePath("r.pdf")});
    EXPECT_EQ(diff.exitCode, 2);
    EXPECT_FALSE(QFile::exists(dir.filePath("r.pdf")));
}
