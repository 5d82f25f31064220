// SPDX-License-Identifier: GPL-3.0-or-later
#include "MessageBoxAnswerer.h"
#include "WindowTest.h"

#include "document/ProjectDocument.h"
#include "output/CompileOutput.h"
#include "output/CompileRun.h"
#include "project/Project.h"
#include "text/ProgramEditor.h"

#include <QAction>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QProgressBar>
#include <QTest>

#include "QtPrinting.h"

#include <gtest/gtest.h>

namespace {

using rs::ui::PageRef;

class CompileTest : public WindowTest {
protected:
    rs::ui::CompileOutput* output() { return window.compileOutput(); }
    bool waitForCompile() {
        return QTest::qWaitFor([&] { return !window.isCompiling(); }, 30000);
    }
    // The manual's muting example in a file of its own, opened and shown.
    QString openMuting() {
        const QString path =
            writeFile(QStringLiteral("muting.sps"),
                      readFile(QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps")));
        EXPECT_TRUE(window.loadFile(path).isEmpty());
        showWindow();
        return path;
    }
};

TEST_F(CompileTest, CompilingOffTheWindowsThreadEndsWithTheOriginalsClosingLine) {
    openMuting();
    action("compileAction")->trigger();
    // The window is free while the compiler runs; the button waits for it.
    EXPECT_TRUE(window.isCompiling() || !output()->closingLine().isEmpty());
    ASSERT_TRUE(waitForCompile());
    EXPECT_EQ(output()->closingLine(), QStringLiteral("0 Error(s) detected Result=OK"));
    EXPECT_TRUE(action("compileAction")->isEnabled());
    // The manual's example leaves Q0.17 without an I/O declaration.
    bool warned = false;
    for (int i = 0; i < output()->rowCount(); ++i)
        warned = warned || output()
                               ->text(i, rs::ui::CompileOutput::MessageColumn)
                               .contains(QStringLiteral("Q0.17"));
    EXPECT_TRUE(warned);
    EXPECT_TRUE(QFile::exists(directory.filePath(QStringLiteral("muting.hps"))));
}

// The window compiles the text it writes from the project, the command line
// the file: every example, its blocks expanded, compiles to the same bytes.
TEST_F(CompileTest, TheWindowsImageIsTheCommandLinesByteForByte) {
    for (const char* example : {"muting.sps", "press-line.sps", "safety-cell.sps",
                                "gateway-line.sps", "two-hand.sps", "estop.sps"}) {
        SCOPED_TRACE(example);
        const QString path =
            writeFile(QString::fromLatin1(example),
                      readFile(QStringLiteral(RUNGSMITH_SOURCE_DIR "/resources/examples/") +
                               QString::fromLatin1(example)));
        ASSERT_TRUE(window.loadFile(path).isEmpty());
        showWindow();
        action("compileAction")->trigger();
        ASSERT_TRUE(waitForCompile());
        ASSERT_EQ(output()->closingLine(), QStringLiteral("0 Error(s) detected Result=OK"));
        const QString cliImage = directory.filePath(QStringLiteral("cli.hps"));
        QProcess cli;
        cli.start(QStringLiteral(RUNGSMITH_CLI),
                  {QStringLiteral("compile"), path, QStringLiteral("-o"), cliImage});
        ASSERT_TRUE(cli.waitForFinished(30000));
        ASSERT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();
        QString windowImage = path;
        windowImage.replace(QStringLiteral(".sps"), QStringLiteral(".hps"));
        const QByteArray ours = readFile(windowImage);
        EXPECT_FALSE(ours.isEmpty());
        EXPECT_TRUE(ours == readFile(cliImage));
    }
}

TEST_F(CompileTest, ACompileShorterThanHalfASecondShowsNoBusyBar) {
    openMuting();
    auto* busy = window.findChild<QProgressBar*>(QStringLiteral("compileProgress"));
    ASSERT_NE(busy, nullptr);
    QElapsedTimer running;
    running.start();
    action("compileAction")->trigger();
    bool shown = false;
    while (window.isCompiling() && running.elapsed() < 30000) {
        shown = shown || busy->isVisible();
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    }
    ASSERT_FALSE(window.isCompiling());
    if (running.elapsed() < rs::ui::CompileRun::kBusyAfterMs) { // as it does, by far
        EXPECT_FALSE(shown);
    }
    EXPECT_FALSE(busy->isVisible());
    EXPECT_EQ(output()->closingLine(), QStringLiteral("0 Error(s) detected Result=OK"));
}

TEST_F(CompileTest, AnErrorIsListedWithItsUnitAndLineAndDoubleClickGoesThere) {
    const QString path = writeFile(QStringLiteral("bad.sps"), "$name Bad\n"
                                                              "! id_pluto:00=000000000000\n"
                                                              "! type_pluto:00=A20,is2\n"
                                                              "! pgm_pluto:00\n"
                                                              "S0.0_0\n"
                                                              "Q0.2 = I0.1\n"
                                                              "Q0.3 = M0.700\n");
    ASSERT_TRUE(window.loadFile(path).isEmpty());
    showWindow();
    window.showPage(PageRef::Kind::Variables, 0);
    action("compileAction")->trigger();
    ASSERT_TRUE(waitForCompile());
    EXPECT_EQ(output()->closingLine(), QStringLiteral("1 Error(s) detected Result=FAILED"));
    EXPECT_FALSE(QFile::exists(directory.filePath(QStringLiteral("bad.hps"))));
    int error = -1;
    for (int i = 0; i < output()->rowCount(); ++i)
        if (output()
                ->text(i, rs::ui::CompileOutput::MessageColumn)
                .startsWith(QStringLiteral("error:")))
            error = i;
    ASSERT_NE(error, -1);
    EXPECT_EQ(output()->text(error, rs::ui::CompileOutput::PlaceColumn),
              QStringLiteral("Pluto 0, line 4:8"));

    const QPoint where = output()->visualRect(output()->model()->index(error, 0)).center();
    QTest::mouseClick(output()->viewport(), Qt::LeftButton, {}, where);
    QTest::mouseDClick(output()->viewport(), Qt::LeftButton, {}, where);
    EXPECT_EQ(window.currentPage().kind, PageRef::Kind::Code);
    int line = -1;
    int column = -1;
    window.editor()->getCursorPosition(&line, &column);
    EXPECT_EQ(line, 3);
    EXPECT_EQ(column, 7);
}

// Issue 17, finding 6: the Output dock belongs to the project compiled.
TEST_F(CompileTest, ClosingTheProjectTakesItsResultAndTheOutputDockAway) {
    openMuting();
    action("compileAction")->trigger();
    ASSERT_TRUE(waitForCompile());
    auto* dock = window.findChild<QDockWidget*>(QStringLiteral("outputDock"));
    ASSERT_TRUE(dock);
    EXPECT_TRUE(dock->isVisible());
    ASSERT_TRUE(window.closeDocument(document()));
    EXPECT_EQ(output()->rowCount(), 0);
    EXPECT_FALSE(dock->isVisible());
}

// Issue 17, finding 1: an image written beside an older file matches no
// source a reviewer can read. Compile asks; each answer keeps them in step.
class CompileUnsavedTest : public CompileTest {
protected:
    void SetUp() override {
        CompileTest::SetUp();
        path = openMuting();
        document()->edit(QStringLiteral("Describe"),
                         [](rs::project::Project& p) { p.description = "edited"; });
        ASSERT_TRUE(document()->isModified());
    }
    QString image() const { return directory.filePath(QStringLiteral("muting.hps")); }
    QString path;
};

TEST_F(CompileUnsavedTest, SaveAndCompileWritesTheImageOfTheSavedFile) {
    MessageBoxAnswerer answerer(QMessageBox::Save);
    action("compileAction")->trigger();
    ASSERT_TRUE(answerer.answered());
    EXPECT_TRUE(answerer.text().contains(QStringLiteral("not saved")));
    ASSERT_TRUE(waitForCompile());
    EXPECT_FALSE(document()->isModified());
    EXPECT_TRUE(readFile(path).contains("edited"));
    EXPECT_TRUE(QFile::exists(image()));
}

TEST_F(CompileUnsavedTest, CheckOnlyWritesNoImageAndLeavesTheFileAlone) {
    const QByteArray saved = readFile(path);
    MessageBoxAnswerer answerer(QMessageBox::Ignore);
    action("compileAction")->trigger();
    ASSERT_TRUE(answerer.answered());
    ASSERT_TRUE(waitForCompile());
    EXPECT_EQ(output()->closingLine(), QStringLiteral("0 Error(s) detected Result=OK"));
    EXPECT_FALSE(QFile::exists(image()));
    EXPECT_EQ(readFile(path), saved);
    EXPECT_TRUE(document()->isModified());
}

TEST_F(CompileUnsavedTest, CancelCompilesNothing) {
    MessageBoxAnswerer answerer(QMessageBox::Cancel);
    action("compileAction")->trigger();
    ASSERT_TRUE(answerer.answered());
    EXPECT_FALSE(window.isCompiling());
    EXPECT_TRUE(output()->closingLine().isEmpty());
    EXPECT_FALSE(QFile::exists(image()));
}

} // namespace
