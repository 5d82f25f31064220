#include "MainWindow.h"
#include "MessageBoxAnswerer.h"
#include "ProblemsView.h"
#include "ProgramEditor.h"
#include "RecentFiles.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>

#include "QtPrinting.h"

#include <gtest/gtest.h>

namespace {

using rs::ui::MainWindow;
using rs::ui::ProblemsView;
using rs::ui::ProgramEditor;

const QByteArray kMessyProject = "$name Press\n"
                                 "! pgm_pluto:00\n"
                                 "s0.0_0\n"
                                 "q0.2 = i0.1*(i0.2+m0.0)   ; run\n";
const QByteArray kCanonicalProject = "$name Press\n"
                                     "! pgm_pluto:00\n"
                                     "S0.0_0\n"
                                     "Q0.2 = I0.1 * (I0.2 + M0.0)    ; run\n";

class MainWindowTest : public ::testing::Test {
protected:
    void SetUp() override {
        // Each test starts from no recent files and no saved layout.
        QSettings().clear();
        ASSERT_TRUE(directory.isValid());
    }

    void TearDown() override {
        // Nothing modified is left behind, so closing asks nothing.
        window.editor()->setModified(false);
        window.close();
    }

    QString writeFile(const QString& name, const QByteArray& bytes) {
        QFile file(directory.filePath(name));
        EXPECT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(bytes);
        return file.fileName();
    }

    static QByteArray readFile(const QString& path) {
        QFile file(path);
        EXPECT_TRUE(file.open(QIODevice::ReadOnly));
        return file.readAll();
    }

    void showWindow() {
        window.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    }

    ProgramEditor* editor() { return window.editor(); }
    ProblemsView* problems() {
        return window.findChild<ProblemsView*>(QStringLiteral("problemsView"));
    }
    QString summary() {
        return window.findChild<QLabel*>(QStringLiteral("problemSummaryLabel"))->text();
    }
    QAction* action(const char* name) {
        auto* found = window.findChild<QAction*>(QString::fromLatin1(name));
        EXPECT_NE(found, nullptr) << name;
        return found;
    }

    QTemporaryDir directory;
    MainWindow window;
};

TEST_F(MainWindowTest, ANewProjectChecksClean) {
    EXPECT_EQ(problems()->topLevelItemCount(), 0);
    EXPECT_EQ(summary(), QStringLiteral("0 errors, 0 warnings"));
    EXPECT_TRUE(window.windowTitle().startsWith(QStringLiteral("untitled.sps[*] — Rungsmith")));
    EXPECT_FALSE(window.isWindowModified());
}

TEST_F(MainWindowTest, TypingAnErrorShowsItAfterAPause) {
    showWindow();
    editor()->setFocus();
    QTest::keyClick(editor(), Qt::Key_End, Qt::ControlModifier);
    QTest::keyClicks(editor(), QStringLiteral("Q0.1 = I0.1 * / (I0.2 + I0.3)"));
    const int line = editor()->lines(); // typed on the last line
    // Not yet, even with events flowing: the text is checked once typing pauses.
    QTest::qWait(MainWindow::kCheckDelayMs / 6);
    EXPECT_EQ(editor()->markersAtLine(line - 1), 0u);
    EXPECT_EQ(problems()->topLevelItemCount(), 0);
    EXPECT_TRUE(window.isWindowModified());

    EXPECT_TRUE(QTest::qWaitFor([&] { return problems()->topLevelItemCount() > 0; },
                                MainWindow::kCheckDelayMs * 5));
    EXPECT_NE(editor()->markersAtLine(line - 1) & (1u << ProgramEditor::ErrorMarker), 0u);
    ASSERT_EQ(problems()->topLevelItemCount(), 1);
    QTreeWidgetItem* item = problems()->topLevelItem(0);
    EXPECT_EQ(item->text(ProblemsView::LocationColumn), QStringLiteral("%1:15").arg(line));
    EXPECT_TRUE(item->text(ProblemsView::MessageColumn).contains(QStringLiteral("negation")));
    EXPECT_FALSE(editor()->annotation(line - 1).isEmpty());
    EXPECT_EQ(summary(), QStringLiteral("1 error, 0 warnings"));

    // Fixing it clears marker, list and summary.
    QTest::keyClick(editor(), Qt::Key_Home);
    QTest::keyClick(editor(), Qt::Key_End, Qt::ShiftModifier);
    QTest::keyClicks(editor(), QStringLiteral("Q0.1 = I0.1"));
    EXPECT_TRUE(QTest::qWaitFor([&] { return problems()->topLevelItemCount() == 0; },
                                MainWindow::kCheckDelayMs * 5));
    EXPECT_EQ(editor()->markersAtLine(line - 1), 0u);
    EXPECT_EQ(summary(), QStringLiteral("0 errors, 0 warnings"));
}

TEST_F(MainWindowTest, DoubleClickingAProblemMovesTheCursorThere) {
    const QString path = writeFile(QStringLiteral("broken.sps"), "! pgm_pluto:00\n"
                                                                 "S0.0_0\n"
                                                                 "Q0.1 = I0.1\n"
                                                                 "Q0.2 = I0.2 ++ I0.3\n"
                                                                 "Q0.3 = q0.x\n");
    ASSERT_TRUE(window.loadFile(path).isEmpty());
    showWindow();
    ASSERT_EQ(problems()->topLevelItemCount(), 2);
    QTreeWidgetItem* second = problems()->topLevelItem(1);
    EXPECT_EQ(second->text(ProblemsView::LocationColumn), QStringLiteral("5:8"));

    const QPoint where = problems()->visualItemRect(second).center();
    // A real double-click starts with a click; QTest's double-click event alone
    // lacks the press that an item view needs to know which row it is on.
    QTest::mouseClick(problems()->viewport(), Qt::LeftButton, {}, where);
    QTest::mouseDClick(problems()->viewport(), Qt::LeftButton, {}, where);
    int line = -1;
    int index = -1;
    editor()->getCursorPosition(&line, &index);
    EXPECT_EQ(line, 4);
    EXPECT_EQ(index, 7);
    EXPECT_TRUE(editor()->hasFocus());
}

TEST_F(MainWindowTest, FormatDocumentCanonicalisesAndOneUndoRestores) {
    const QString path = writeFile(QStringLiteral("messy.sps"), kMessyProject);
    ASSERT_TRUE(window.loadFile(path).isEmpty());
    QAction* format = action("formatDocumentAction");
    EXPECT_EQ(format->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));

    format->trigger();
    EXPECT_EQ(editor()->textBytes(), kCanonicalProject);
    EXPECT_TRUE(window.isWindowModified());

    action("undoAction")->trigger();
    EXPECT_EQ(editor()->textBytes(), kMessyProject);
    action("redoAction")->trigger();
    EXPECT_EQ(editor()->textBytes(), kCanonicalProject);

    format->trigger(); // already canonical: nothing to undo
    action("undoAction")->trigger();
    EXPECT_EQ(editor()->textBytes(), kMessyProject);
}

TEST_F(MainWindowTest, FormatDocumentLeavesATextWithErrorsAlone) {
    const QByteArray broken = "! pgm_pluto:00\ns0.0_0\nq0.1 = i0.1 * / (i0.2 + i0.3)\n";
    ASSERT_TRUE(window.loadFile(writeFile(QStringLiteral("broken.sps"), broken)).isEmpty());
    action("formatDocumentAction")->trigger();
    EXPECT_EQ(editor()->textBytes(), broken);
    EXPECT_FALSE(editor()->isUndoAvailable());
}

TEST_F(MainWindowTest, SaveThenReopenGivesTheSameText) {
    // Spelling the formatter would change, Windows line ends and a Latin-1 byte:
    // Save writes what the editor holds, nothing else.
    const QString path = writeFile(QStringLiteral("press.sps"),
                                   "$name  Press\r\n! pgm_pluto:00\r\ns0.0_0\r\n; caf\xe9\r\n");
    ASSERT_TRUE(window.loadFile(path).isEmpty());
    EXPECT_TRUE(window.windowTitle().startsWith(QStringLiteral("press.sps[*] — Rungsmith")));
    showWindow();
    editor()->setFocus();
    QTest::keyClick(editor(), Qt::Key_End, Qt::ControlModifier);
    QTest::keyClicks(editor(), QStringLiteral("q0.1 =   i0.1"));
    QTest::keyClick(editor(), Qt::Key_Return);
    EXPECT_TRUE(window.isWindowModified());

    action("saveAction")->trigger();
    EXPECT_FALSE(window.isWindowModified());
    const QByteArray saved = readFile(path);
    EXPECT_EQ(saved, editor()->textBytes());
    EXPECT_TRUE(saved.endsWith("; caf\xe9\r\nq0.1 =   i0.1\r\n"));

    MainWindow reopened;
    ASSERT_TRUE(reopened.loadFile(path).isEmpty());
    EXPECT_EQ(reopened.editor()->textBytes(), saved);
}

TEST_F(MainWindowTest, AFailedSaveIsReportedAndTheTextStaysModified) {
    QDir(directory.path()).mkdir(QStringLiteral("gone"));
    const QString path = writeFile(QStringLiteral("gone/press.sps"), kCanonicalProject);
    ASSERT_TRUE(window.loadFile(path).isEmpty());
    editor()->insert(QStringLiteral("; my change\n"));
    ASSERT_TRUE(QDir(directory.filePath(QStringLiteral("gone"))).removeRecursively());

    MessageBoxAnswerer answerer(QMessageBox::Ok);
    action("saveAction")->trigger();
    ASSERT_TRUE(answerer.answered());
    EXPECT_TRUE(answerer.text().contains(path));
    EXPECT_TRUE(window.isWindowModified());
}

TEST_F(MainWindowTest, OpeningAMissingFileReportsItAndKeepsTheText) {
    const QByteArray before = editor()->textBytes();
    const QString title = window.windowTitle();
    const QString missing = directory.filePath(QStringLiteral("no-such-project.sps"));

    MessageBoxAnswerer answerer(QMessageBox::Ok);
    EXPECT_FALSE(window.openFile(missing));
    ASSERT_TRUE(answerer.answered());
    EXPECT_TRUE(answerer.text().contains(missing));
    EXPECT_TRUE(answerer.informativeText().contains(QStringLiteral("No such file")));
    EXPECT_EQ(editor()->textBytes(), before);
    EXPECT_EQ(window.windowTitle(), title);
    EXPECT_TRUE(rs::ui::RecentFiles().paths().isEmpty());
}

TEST_F(MainWindowTest, OpeningADirectoryReportsIt) {
    MessageBoxAnswerer answerer(QMessageBox::Ok);
    EXPECT_FALSE(window.openFile(directory.path()));
    EXPECT_TRUE(answerer.answered());
}

TEST_F(MainWindowTest, UnsavedChangesAreOfferedForSavingBeforeOpening) {
    const QString other = writeFile(QStringLiteral("other.sps"), kCanonicalProject);
    editor()->insert(QStringLiteral("; my change\n"));
    const QByteArray changed = editor()->textBytes();

    {
        MessageBoxAnswerer cancel(QMessageBox::Cancel);
        EXPECT_FALSE(window.openFile(other));
        ASSERT_TRUE(cancel.answered());
        EXPECT_EQ(cancel.buttons(), QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
        EXPECT_EQ(editor()->textBytes(), changed);
    }
    {
        MessageBoxAnswerer discard(QMessageBox::Discard);
        EXPECT_TRUE(window.openFile(other));
        EXPECT_TRUE(discard.answered());
        EXPECT_EQ(editor()->textBytes(), kCanonicalProject);
    }
}

TEST_F(MainWindowTest, ClosingWithUnsavedChangesCanBeCancelled) {
    showWindow();
    editor()->insert(QStringLiteral("; my change\n"));
    MessageBoxAnswerer cancel(QMessageBox::Cancel);
    EXPECT_FALSE(window.close());
    EXPECT_TRUE(cancel.answered());
    EXPECT_TRUE(window.isVisible());
}

TEST_F(MainWindowTest, OpenedFilesBecomeRecentFiles) {
    const QString first = writeFile(QStringLiteral("first.sps"), kCanonicalProject);
    const QString second = writeFile(QStringLiteral("second.sps"), kCanonicalProject);
    ASSERT_TRUE(window.openFile(first));
    ASSERT_TRUE(window.openFile(second));
    EXPECT_EQ(rs::ui::RecentFiles().paths(), QStringList({second, first}));

    auto* recent = window.findChild<QMenu*>(QStringLiteral("recentMenu"));
    emit window.findChild<QMenu*>(QStringLiteral("fileMenu"))->aboutToShow();
    ASSERT_GE(recent->actions().size(), 2);
    recent->actions().at(1)->trigger();
    EXPECT_TRUE(window.windowTitle().startsWith(QStringLiteral("first.sps")));
}

TEST_F(MainWindowTest, WindowGeometryOutlivesTheWindow) {
    showWindow();
    window.resize(900, 600);
    ASSERT_TRUE(window.close());

    MainWindow next;
    next.restoreLayout();
    EXPECT_EQ(next.size(), QSize(900, 600));
}

TEST_F(MainWindowTest, ShowUnitFindsTheUnitsCode) {
    const QString path = writeFile(QStringLiteral("two.sps"), "! pgm_pluto:00\n"
                                                              "S0.0_0\n"
                                                              "Q0.1 = I0.1\n"
                                                              "! pgm_pluto:01\n"
                                                              "S1.0_0\n"
                                                              "Q1.1 = I1.1\n");
    ASSERT_TRUE(window.loadFile(path).isEmpty());
    EXPECT_TRUE(window.showUnit(1));
    int line = -1;
    int index = -1;
    editor()->getCursorPosition(&line, &index);
    EXPECT_EQ(line, 3);
    EXPECT_FALSE(window.showUnit(2));
}

TEST_F(MainWindowTest, TheExampleIsTheBundledMutingProjectAndChecksClean) {
    window.showExample();
    EXPECT_TRUE(window.windowTitle().startsWith(QStringLiteral("muting.sps")));
    EXPECT_TRUE(editor()->textBytes().startsWith("$name Example, manual\n"));
    EXPECT_EQ(problems()->topLevelItemCount(), 0);
}

TEST(MainWindowTranslation, SwedishMenus) {
    QTranslator swedish;
    ASSERT_TRUE(swedish.load(QLocale(QLocale::Swedish), QStringLiteral("rungsmith"),
                             QStringLiteral("_"), QStringLiteral(":/i18n")));
    QApplication::installTranslator(&swedish);
    {
        MainWindow window;
        EXPECT_EQ(window.findChild<QMenu*>(QStringLiteral("fileMenu"))->title(),
                  QStringLiteral("&Arkiv"));
        EXPECT_EQ(window.findChild<QLabel*>(QStringLiteral("problemSummaryLabel"))->text(),
                  QStringLiteral("0 fel, 0 varningar"));
    }
    QApplication::removeTranslator(&swedish);
}

} // namespace
