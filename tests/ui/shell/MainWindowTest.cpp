// SPDX-License-Identifier: GPL-3.0-or-later
#include "WindowTest.h"

#include "DialogDriver.h"
#include "MessageBoxAnswerer.h"
#include "document/ProjectDocument.h"
#include "ladder/LadderPage.h"
#include "output/ProblemsView.h"
#include "pages/SignatureLabel.h"
#include "pages/VariablesPage.h"
#include "project/ProjectFile.h"
#include "project/UnitText.h"
#include "shell/ProjectTree.h"
#include "shell/RecentFiles.h"
#include "text/ProgramEditor.h"
#include "text/TextPage.h"

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QDir>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QProcess>
#include <QStackedWidget>
#include <QTest>
#include <QTranslator>

#include "QtPrinting.h"

#include <gtest/gtest.h>

namespace {

using rs::ui::MainWindow;
using rs::ui::PageRef;
using rs::ui::ProblemsView;
using rs::ui::ProgramEditor;

const QByteArray kMessyProject = "$name Press\n"
                                 "! id_pluto:00=000000000000\n"
                                 "! pgm_pluto:00\n"
                                 "s0.0_0\n"
                                 "q0.2 = i0.1*(i0.2+m0.0)   ; run\n";
const QByteArray kCanonicalProject = "$name Press\n"
                                     "! id_pluto:00=000000000000\n"
                                     "! pgm_pluto:00\n"
                                     "S0.0_0\n"
                                     "Q0.2 = I0.1 * (I0.2 + M0.0)    ; run\n";
const QByteArray kCanonicalUnit = "! pgm_pluto:00\n"
                                  "S0.0_0\n"
                                  "Q0.2 = I0.1 * (I0.2 + M0.0)    ; run\n";

class MainWindowTest : public WindowTest {
protected:
    ProgramEditor* editor() { return window.editor(); }
    ProblemsView* problems() {
        return window.findChild<ProblemsView*>(QStringLiteral("problemsView"));
    }
    QString summary() {
        return window.findChild<QLabel*>(QStringLiteral("problemSummaryLabel"))->text();
    }
    QWidget* currentPage() {
        return window.findChild<QStackedWidget*>(QStringLiteral("pages"))->currentWidget();
    }
    // A unit's code opens as ladder; these tests type it.
    void showCodeAsText() { ASSERT_TRUE(window.showPage(PageRef::Kind::Code, 0)); }
};

TEST_F(MainWindowTest, WithoutAProjectTheWindowSaysHowToStart) {
    EXPECT_EQ(currentPage()->objectName(), QStringLiteral("welcomePage"));
    EXPECT_EQ(window.windowTitle(), QStringLiteral("Rungsmith"));
    EXPECT_FALSE(action("saveAction")->isEnabled());
    EXPECT_FALSE(action("compileAction")->isEnabled());
    EXPECT_FALSE(action("undoAction")->isEnabled());
    EXPECT_TRUE(action("newAction")->isEnabled());
}

TEST_F(MainWindowTest, TheExampleOpensOnItsUnitsCode) {
    window.showExample();
    EXPECT_TRUE(window.windowTitle().startsWith(QStringLiteral("Example, manual.sps[*] — ")));
    EXPECT_FALSE(window.isWindowModified());
    EXPECT_EQ(currentPage(), static_cast<QWidget*>(window.ladderPage()));
    EXPECT_EQ(window.currentPage().kind, PageRef::Kind::Ladder);
    showCodeAsText();
    EXPECT_TRUE(editor()->textBytes().startsWith("! pgm_pluto:00\n"));
    EXPECT_EQ(problems()->topLevelItemCount(), 0);
    EXPECT_EQ(summary(), QStringLiteral("0 errors, 0 warnings"));
    // The tree: Projects > Example > Pluto 0 — A20 > pages and sequence 1.
    rs::ui::ProjectTree* tree = window.projectTree();
    QTreeWidgetItem* unit = tree->itemFor({PageRef::Kind::Unit, document(), 0});
    ASSERT_NE(unit, nullptr);
    EXPECT_EQ(unit->text(0), QStringLiteral("Pluto 0 — A20"));
    QStringList children;
    for (int i = 0; i < unit->childCount(); ++i)
        children << unit->child(i)->text(0);
    EXPECT_EQ(children, (QStringList{QStringLiteral("I/O Options"), QStringLiteral("Variables"),
                                     QStringLiteral("PLC Code"), QStringLiteral("Sequence 1")}));
}

TEST_F(MainWindowTest, TypingAnErrorShowsItAfterAPauseAndKeepsItOutOfTheProject) {
    // Only the typed problem: the compiler's check would add the example's
    // unconfigured Q0.17.
    window.textPage()->setWarnUnconfiguredIo(false);
    window.showExample();
    showCodeAsText();
    showWindow();
    const QByteArray before = projectText();
    editor()->setFocus();
    QTest::keyClick(editor(), Qt::Key_End, Qt::ControlModifier);
    QTest::keyClicks(editor(), QStringLiteral("Q0.1 = I0.1 * / (I0.2 + I0.3)"));
    const int line = editor()->lines(); // typed on the last line
    // Not yet, even with events flowing: the text is read once typing pauses.
    QTest::qWait(MainWindow::kCheckDelayMs / 6);
    EXPECT_EQ(editor()->markersAtLine(line - 1), 0u);
    EXPECT_EQ(problems()->topLevelItemCount(), 0);

    EXPECT_TRUE(QTest::qWaitFor([&] { return problems()->topLevelItemCount() > 0; },
                                MainWindow::kCheckDelayMs * 5));
    EXPECT_NE(editor()->markersAtLine(line - 1) & (1u << ProgramEditor::ErrorMarker), 0u);
    ASSERT_EQ(problems()->topLevelItemCount(), 1);
    QTreeWidgetItem* item = problems()->topLevelItem(0);
    EXPECT_EQ(item->text(ProblemsView::LocationColumn), QStringLiteral("%1:15").arg(line));
    EXPECT_TRUE(item->text(ProblemsView::MessageColumn).contains(QStringLiteral("negation")));
    EXPECT_EQ(summary(), QStringLiteral("1 error, 0 warnings"));
    EXPECT_EQ(projectText(), before); // what has errors is not read into the project

    // Fixing it clears marker and list, and the line is in the project.
    QTest::keyClick(editor(), Qt::Key_Home);
    QTest::keyClick(editor(), Qt::Key_End, Qt::ShiftModifier);
    QTest::keyClicks(editor(), QStringLiteral("Q0.1 = I0.1"));
    EXPECT_TRUE(QTest::qWaitFor([&] { return problems()->topLevelItemCount() == 0; },
                                MainWindow::kCheckDelayMs * 5));
    EXPECT_EQ(editor()->markersAtLine(line - 1), 0u);
    EXPECT_TRUE(projectText().endsWith("Q0.1 = I0.1\n"));
    EXPECT_TRUE(window.isWindowModified());
}

TEST_F(MainWindowTest, LeavingCodeWithErrorsAsksToKeepEditingOrDiscard) {
    window.showExample();
    showCodeAsText();
    showWindow();
    const QByteArray before = projectText();
    editor()->setFocus();
    QTest::keyClick(editor(), Qt::Key_End, Qt::ControlModifier);
    QTest::keyClicks(editor(), QStringLiteral("Q0.1 = ("));
    {
        MessageBoxAnswerer keep(QMessageBox::Cancel); // no such button: the default, Keep Editing
        EXPECT_FALSE(window.showPage(PageRef::Kind::Variables, 0));
        EXPECT_TRUE(keep.answered());
        EXPECT_EQ(currentPage(), static_cast<QWidget*>(window.textPage()));
        EXPECT_TRUE(editor()->textBytes().endsWith("Q0.1 = ("));
    }
    {
        MessageBoxAnswerer discard(QMessageBox::Discard);
        EXPECT_TRUE(window.showPage(PageRef::Kind::Variables, 0));
        EXPECT_TRUE(discard.answered());
        EXPECT_EQ(currentPage(), static_cast<QWidget*>(window.variablesPage()));
    }
    EXPECT_EQ(projectText(), before);
}

TEST_F(MainWindowTest, DoubleClickingAProblemMovesTheCursorThere) {
    // Only the typed problem: the compiler's check would add the example's
    // unconfigured Q0.17.
    window.textPage()->setWarnUnconfiguredIo(false);
    window.showExample();
    showCodeAsText();
    showWindow();
    editor()->setFocus();
    QTest::keyClick(editor(), Qt::Key_End, Qt::ControlModifier);
    QTest::keyClicks(editor(), QStringLiteral("Q0.3 = q0.x"));
    ASSERT_TRUE(QTest::qWaitFor([&] { return problems()->topLevelItemCount() == 1; },
                                MainWindow::kCheckDelayMs * 5));
    const int line = editor()->lines();
    QTreeWidgetItem* problem = problems()->topLevelItem(0);
    EXPECT_EQ(problem->text(ProblemsView::LocationColumn), QStringLiteral("%1:8").arg(line));
    QTest::keyClick(editor(), Qt::Key_Home, Qt::ControlModifier);

    const QPoint where = problems()->visualItemRect(problem).center();
    // A real double-click starts with a click; QTest's double-click event alone
    // lacks the press that an item view needs to know which row it is on.
    QTest::mouseClick(problems()->viewport(), Qt::LeftButton, {}, where);
    QTest::mouseDClick(problems()->viewport(), Qt::LeftButton, {}, where);
    int cursorLine = -1;
    int index = -1;
    editor()->getCursorPosition(&cursorLine, &index);
    EXPECT_EQ(cursorLine, line - 1);
    EXPECT_EQ(index, 7);
    EXPECT_TRUE(editor()->hasFocus());
}

TEST_F(MainWindowTest, FormatDocumentRewritesWhatWasTypedCanonically) {
    ASSERT_TRUE(window.loadFile(writeFile(QStringLiteral("messy.sps"), kMessyProject)).isEmpty());
    showCodeAsText();
    showWindow();
    // The code shows as the project holds it: canonical.
    EXPECT_EQ(editor()->textBytes(), kCanonicalUnit);
    editor()->setFocus();
    QTest::keyClick(editor(), Qt::Key_End, Qt::ControlModifier);
    QTest::keyClicks(editor(), QStringLiteral("q0.3=q0.2"));
    QAction* format = action("formatDocumentAction");
    EXPECT_EQ(format->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
    format->trigger();
    EXPECT_EQ(editor()->textBytes(), kCanonicalUnit + "Q0.3 = Q0.2\n");
    EXPECT_TRUE(projectText().endsWith("Q0.3 = Q0.2\n"));
    // Formatting itself changes nothing in the project: one undo takes the line away.
    action("undoAction")->trigger();
    EXPECT_EQ(editor()->textBytes(), kCanonicalUnit);
}

TEST_F(MainWindowTest, AFileWithErrorsOpensAsTextUntilItReadsCleanly) {
    const QByteArray broken = "! id_pluto:00=000000000000\n! pgm_pluto:00\ns0.0_0\n"
                              "q0.1 = i0.1 * / (i0.2 + i0.3)\n";
    ASSERT_TRUE(window.loadFile(writeFile(QStringLiteral("broken.sps"), broken)).isEmpty());
    showWindow();
    ASSERT_TRUE(document()->isDamaged());
    EXPECT_EQ(window.currentPage().kind, PageRef::Kind::ProjectText);
    EXPECT_EQ(editor()->textBytes(), broken);
    EXPECT_EQ(window.projectTree()->itemFor({PageRef::Kind::Unit, document(), 0}), nullptr);
    EXPECT_EQ(problems()->topLevelItemCount(), 1);
    action("formatDocumentAction")->trigger();
    EXPECT_EQ(editor()->textBytes(), broken);

    // Saving keeps every line, also the one with the error.
    const QString copy = directory.filePath(QStringLiteral("copy.sps"));
    ASSERT_TRUE(window.saveDocumentAs(document(), copy));
    EXPECT_EQ(readFile(copy), broken);

    editor()->setFocus();
    QTest::keyClick(editor(), Qt::Key_End, Qt::ControlModifier);
    QTest::keyClick(editor(), Qt::Key_Up);
    QTest::keyClick(editor(), Qt::Key_End, Qt::ShiftModifier);
    QTest::keyClicks(editor(), QStringLiteral("q0.1 = i0.1"));
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return !document()->isDamaged(); }, MainWindow::kCheckDelayMs * 5));
    EXPECT_NE(window.projectTree()->itemFor({PageRef::Kind::Unit, document(), 0}), nullptr);
    EXPECT_EQ(window.currentPage().kind, PageRef::Kind::Code);
    EXPECT_TRUE(window.isWindowModified());
}

TEST_F(MainWindowTest, SaveWritesTheCanonicalTextAndReopeningGivesItBack) {
    const QString path = writeFile(QStringLiteral("press.sps"), kMessyProject);
    ASSERT_TRUE(window.loadFile(path).isEmpty());
    EXPECT_TRUE(window.windowTitle().startsWith(QStringLiteral("press.sps[*] — Rungsmith")));
    showCodeAsText();
    showWindow();
    editor()->setFocus();
    QTest::keyClick(editor(), Qt::Key_End, Qt::ControlModifier);
    QTest::keyClicks(editor(), QStringLiteral("q0.3 =   q0.2"));
    QTest::keyClick(editor(), Qt::Key_Return);
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return window.isWindowModified(); }, MainWindow::kCheckDelayMs * 5));

    action("saveAction")->trigger();
    EXPECT_FALSE(window.isWindowModified());
    const QByteArray saved = readFile(path);
    EXPECT_EQ(saved, kCanonicalProject + "Q0.3 = Q0.2\n");

    MainWindow reopened;
    ASSERT_TRUE(reopened.loadFile(path).isEmpty());
    EXPECT_EQ(reopened.currentDocument()->fileText(), saved);
    ASSERT_TRUE(reopened.saveDocument(reopened.currentDocument()));
    EXPECT_EQ(readFile(path), saved);
}

TEST_F(MainWindowTest, AFailedSaveIsReportedAndTheProjectStaysModified) {
    QDir(directory.path()).mkdir(QStringLiteral("gone"));
    const QString path = writeFile(QStringLiteral("gone/press.sps"), kCanonicalProject);
    ASSERT_TRUE(window.loadFile(path).isEmpty());
    document()->edit(QStringLiteral("Describe"),
                     [](rs::project::Project& p) { p.description = "changed"; });
    ASSERT_TRUE(QDir(directory.filePath(QStringLiteral("gone"))).removeRecursively());

    MessageBoxAnswerer answerer(QMessageBox::Ok);
    action("saveAction")->trigger();
    ASSERT_TRUE(answerer.answered());
    EXPECT_TRUE(answerer.text().contains(QDir::toNativeSeparators(path)));
    EXPECT_TRUE(window.isWindowModified());
}

TEST_F(MainWindowTest, OpeningAMissingFileReportsIt) {
    const QString missing = directory.filePath(QStringLiteral("no-such-project.sps"));
    MessageBoxAnswerer answerer(QMessageBox::Ok);
    EXPECT_FALSE(window.openFile(missing));
    ASSERT_TRUE(answerer.answered());
    EXPECT_TRUE(answerer.text().contains(missing));
    EXPECT_TRUE(answerer.informativeText().contains(QStringLiteral("No such file")));
    EXPECT_TRUE(window.documents().empty());
    EXPECT_TRUE(rs::ui::RecentFiles().paths().isEmpty());
}

TEST_F(MainWindowTest, SeveralProjectsAreOpenAtOnceAndOneCanBeClosed) {
    const QString first = writeFile(QStringLiteral("first.sps"), kCanonicalProject);
    const QString second = writeFile(QStringLiteral("second.sps"), kMessyProject);
    ASSERT_TRUE(window.openFile(first));
    ASSERT_TRUE(window.openFile(second));
    ASSERT_TRUE(window.openFile(first)); // already open: shown, not opened twice
    ASSERT_EQ(window.documents().size(), 2u);
    EXPECT_EQ(rs::ui::RecentFiles().paths(), QStringList({first, second}));
    EXPECT_EQ(window.projectTree()->topLevelItem(0)->childCount(), 2);

    rs::ui::ProjectDocument* firstDocument = window.documents().front();
    firstDocument->edit(QStringLiteral("Describe"),
                        [](rs::project::Project& p) { p.description = "changed"; });
    {
        MessageBoxAnswerer cancel(QMessageBox::Cancel);
        EXPECT_FALSE(window.closeDocument(firstDocument));
        EXPECT_EQ(cancel.buttons(), QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
        EXPECT_EQ(window.documents().size(), 2u);
    }
    MessageBoxAnswerer discard(QMessageBox::Discard);
    EXPECT_TRUE(window.closeDocument(firstDocument));
    ASSERT_EQ(window.documents().size(), 1u);
    EXPECT_EQ(readFile(first), kCanonicalProject);
}

TEST_F(MainWindowTest, SaveAllSavesEveryModifiedProject) {
    const QString first = writeFile(QStringLiteral("first.sps"), kCanonicalProject);
    const QString second = writeFile(QStringLiteral("second.sps"), kMessyProject);
    ASSERT_TRUE(window.loadFile(first).isEmpty());
    ASSERT_TRUE(window.loadFile(second).isEmpty());
    for (rs::ui::ProjectDocument* d : window.documents())
        d->edit(QStringLiteral("Describe"),
                [](rs::project::Project& p) { p.description = "both"; });
    action("saveAllAction")->trigger();
    for (rs::ui::ProjectDocument* d : window.documents())
        EXPECT_FALSE(d->isModified());
    EXPECT_TRUE(readFile(first).contains(";@project description=\"both\""));
    EXPECT_TRUE(readFile(second).contains(";@project description=\"both\""));
}

TEST_F(MainWindowTest, ClosingWithUnsavedChangesCanBeCancelled) {
    window.showExample();
    showWindow();
    document()->edit(QStringLiteral("Describe"),
                     [](rs::project::Project& p) { p.description = "changed"; });
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
    ASSERT_TRUE(window.closeDocument(window.documents().front()));

    auto* recent = window.findChild<QMenu*>(QStringLiteral("recentMenu"));
    emit window.findChild<QMenu*>(QStringLiteral("fileMenu"))->aboutToShow();
    ASSERT_GE(recent->actions().size(), 2);
    recent->actions().at(1)->trigger();
    EXPECT_TRUE(window.windowTitle().startsWith(QStringLiteral("first.sps")));
    EXPECT_EQ(window.documents().size(), 2u);
}

TEST_F(MainWindowTest, WindowGeometryOutlivesTheWindow) {
    showWindow();
    window.resize(900, 600);
    ASSERT_TRUE(window.close());

    MainWindow next;
    next.restoreLayout();
    EXPECT_EQ(next.size(), QSize(900, 600));
}

TEST_F(MainWindowTest, ExportProgramTextWritesTheLanguageAlone) {
    const QString path =
        writeFile(QStringLiteral("described.sps"), "$name Press\n"
                                                   ";@project description=\"Two presses\"\n"
                                                   "! id_pluto:00=000000000000\n"
                                                   ";@var I0.1 description=\"Start\"\n"
                                                   "! pgm_pluto:00\n"
                                                   "S0.0_0\n"
                                                   "Q0.2 = I0.1\n");
    ASSERT_TRUE(window.loadFile(path).isEmpty());
    const QString out = directory.filePath(QStringLiteral("program.sps"));
    ASSERT_TRUE(window.exportProgramText(document(), out));
    EXPECT_EQ(readFile(out), "$name Press\n"
                             "! id_pluto:00=000000000000\n"
                             "! pgm_pluto:00\n"
                             "S0.0_0\n"
                             "Q0.2 = I0.1\n");
}

TEST(MainWindowTranslation, SwedishAndGermanMenus) {
    for (const auto& [language, file, summary] :
         {std::tuple{QLocale::Swedish, QStringLiteral("&Arkiv"),
                     QStringLiteral("0 fel, 0 varningar")},
          std::tuple{QLocale::German, QStringLiteral("&Datei"),
                     QStringLiteral("0 Fehler, 0 Warnungen")}}) {
        QTranslator translator;
        ASSERT_TRUE(translator.load(QLocale(language), QStringLiteral("rungsmith"),
                                    QStringLiteral("_"), QStringLiteral(":/i18n")));
        QApplication::installTranslator(&translator);
        {
            MainWindow window;
            window.showExample();
            EXPECT_EQ(window.findChild<QMenu*>(QStringLiteral("fileMenu"))->title(), file);
            EXPECT_EQ(window.findChild<QLabel*>(QStringLiteral("problemSummaryLabel"))->text(),
                      summary);
            window.currentDocument()->setModifiedWithoutUndo(false);
        }
        QApplication::removeTranslator(&translator);
    }
}

TEST_F(MainWindowTest, CtrlYRedoesAsCtrlShiftZDoes) {
    ASSERT_TRUE(
        window.loadFile(writeFile(QStringLiteral("press.sps"), kCanonicalProject)).isEmpty());
    showWindow();
    const std::string before = rs::project::writeProject(document()->project());
    document()->edit(QStringLiteral("Rename"), [](rs::project::Project& project) {
        project.libraries = {"Rungsmith_Basics"};
    });
    const std::string edited = rs::project::writeProject(document()->project());
    ASSERT_NE(edited, before);
    for (const QKeySequence& redo :
         {QKeySequence(Qt::CTRL | Qt::Key_Y), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z)}) {
        QTest::keySequence(&window, QKeySequence(Qt::CTRL | Qt::Key_Z));
        EXPECT_EQ(rs::project::writeProject(document()->project()), before);
        QTest::keySequence(&window, redo);
        EXPECT_EQ(rs::project::writeProject(document()->project()), edited)
            << redo.toString().toStdString();
    }
}

TEST_F(MainWindowTest, TheWelcomePageListsRecentProjectsAndOpensOneByKey) {
    const QString first = writeFile(QStringLiteral("first.sps"), kCanonicalProject);
    const QString second = writeFile(QStringLiteral("second.sps"), kCanonicalProject);
    ASSERT_TRUE(window.openFile(first));
    ASSERT_TRUE(window.openFile(second));
    ASSERT_TRUE(window.closeDocument(window.documents().back()));
    ASSERT_TRUE(window.closeDocument(window.documents().front()));
    showWindow();
    EXPECT_EQ(currentPage()->objectName(), QStringLiteral("welcomePage"));
    auto* recent = currentPage()->findChild<QListWidget*>(QStringLiteral("recentProjects"));
    ASSERT_NE(recent, nullptr);
    ASSERT_EQ(recent->count(), 2);
    EXPECT_TRUE(recent->isVisibleTo(currentPage()));
    EXPECT_TRUE(recent->item(0)->text().startsWith(QStringLiteral("second.sps")));
    recent->setFocus();
    QTest::keyClick(recent, Qt::Key_Down);
    QTest::keyClick(recent, Qt::Key_Return);
    ASSERT_EQ(window.documents().size(), 1u);
    EXPECT_TRUE(window.windowTitle().startsWith(QStringLiteral("first.sps")));
}

// Issue 17, finding 2: what F7 rejects is marked in the text as it is typed.
TEST_F(MainWindowTest, TheTextViewMarksWhatTheCompilerRejectsAfterThePause) {
    ASSERT_TRUE(window
                    .loadFile(writeFile(QStringLiteral("a20.sps"), "$name A20\n"
                                                                   "! id_pluto:00=000000000000\n"
                                                                   "! type_pluto:00=A20,is2\n"
                                                                   "! pgm_pluto:00\n"
                                                                   "S0.0_0\n"
                                                                   "Q0.2 = I0.1\n"))
                    .isEmpty());
    showWindow();
    showCodeAsText();
    editor()->setFocus();
    QTest::keyClick(editor(), Qt::Key_End, Qt::ControlModifier);
    QTest::keyClicks(editor(), QStringLiteral("Q0.3 = I0.99 * I0.0"));
    const int line = editor()->lines();
    rs::ui::TextPage* page = window.textPage();
    ASSERT_NE(page, nullptr);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return rs::lang::errorCount(page->diagnostics()) > 0 && !page->isChecking(); },
        MainWindow::kCheckDelayMs * 20));
    EXPECT_NE(editor()->markersAtLine(line - 1) & (1u << ProgramEditor::ErrorMarker), 0u);
    bool named = false;
    for (const auto& diagnostic : page->diagnostics())
        if (diagnostic.severity == rs::lang::Severity::Error) {
            EXPECT_EQ(diagnostic.line, line);
            named = named || diagnostic.message.find("I0.99") != std::string::npos;
        }
    EXPECT_TRUE(named);
    EXPECT_TRUE(summary().startsWith(QStringLiteral("1 error")) ||
                summary().startsWith(QStringLiteral("2 errors")))
        << summary().toStdString();
    // Mended, the marks go.
    QTest::keyClick(editor(), Qt::Key_Home);
    QTest::keyClick(editor(), Qt::Key_End, Qt::ShiftModifier);
    QTest::keyClicks(editor(), QStringLiteral("Q0.3 = I0.2 * I0.0"));
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return rs::lang::errorCount(page->diagnostics()) == 0 && !page->isChecking(); },
        MainWindow::kCheckDelayMs * 20));
    EXPECT_TRUE(summary().startsWith(QStringLiteral("0 errors"))) << summary().toStdString();
}

// Issue 23: the text view checks only the unit typed in, with what the
// other units' code uses; a change of another unit (or its undo) is seen.
TEST_F(MainWindowTest, TheTextViewsCheckFollowsWhatTheOtherUnitsUse) {
    ASSERT_TRUE(window
                    .loadFile(writeFile(QStringLiteral("two.sps"), "$name Two\n"
                                                                   "! id_pluto:00=000000000000\n"
                                                                   "! type_pluto:00=A20,is3\n"
                                                                   "! id_pluto:01=000000000000\n"
                                                                   "! type_pluto:01=A20,is3\n"
                                                                   "! pgm_pluto:00\n"
                                                                   "! GM0.3=Shared\n"
                                                                   "S0.0_0\n"
                                                                   "GM0.4 = I0.1\n"
                                                                   "! pgm_pluto:01\n"
                                                                   "S1.0_0\n"
                                                                   "Q1.2 = GM0.3\n"))
                    .isEmpty());
    showWindow();
    showCodeAsText();
    rs::ui::TextPage* page = window.textPage();
    ASSERT_NE(page, nullptr);
    const auto unused = [&] {
        for (const auto& diagnostic : page->diagnostics())
            if (diagnostic.message == "'Shared' (GM0.3) is named but never used")
                return true;
        return false;
    };
    const auto checked = [&] {
        return QTest::qWaitFor([&] { return !page->isChecking(); }, MainWindow::kCheckDelayMs * 20);
    };
    ASSERT_TRUE(checked());
    EXPECT_FALSE(unused()) << "unit 1 reads it";

    rs::project::Project edited = document()->project();
    const auto read = rs::project::readUnitText(edited, 1, "! pgm_pluto:01\nS1.0_0\nQ1.2 = I1.0\n");
    ASSERT_TRUE(read.ok());
    document()->replace(QStringLiteral("another unit"), read.project);
    ASSERT_TRUE(QTest::qWaitFor([&] { return unused() && !page->isChecking(); },
                                MainWindow::kCheckDelayMs * 20));
    document()->undoStack()->undo();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !unused() && !page->isChecking(); },
                                MainWindow::kCheckDelayMs * 20));
}

// Issue 18: the project and unit pages show the program signatures that
// rungsmith-cli signature prints, and follow an edit of the code.
TEST_F(MainWindowTest, TheProjectAndUnitPagesShowTheProgramSignatures) {
    const QString file = QStringLiteral(RUNGSMITH_SOURCE_DIR "/resources/examples/press-line.sps");
    QProcess cli;
    cli.start(QStringLiteral(RUNGSMITH_CLI), {QStringLiteral("signature"), file});
    ASSERT_TRUE(cli.waitForFinished(30000));
    const QStringList printed =
        QString::fromUtf8(cli.readAllStandardOutput()).split(u'\n', Qt::SkipEmptyParts);
    ASSERT_EQ(printed.size(), 3);
    ASSERT_TRUE(window.loadFile(file).isEmpty());
    showWindow();
    auto shown = [&](const char* name) {
        auto* label = window.findChild<rs::ui::SignatureLabel*>(QLatin1String(name));
        EXPECT_NE(label, nullptr) << name;
        if (!label || !QTest::qWaitFor([&] { return !label->isComputing(); }, 30000))
            return QString();
        return label->text();
    };
    ASSERT_TRUE(window.showPage(PageRef::Kind::Project, 0));
    EXPECT_EQ(QStringLiteral("project ") + shown("projectSignature"), printed[2]);
    ASSERT_TRUE(window.showPage(PageRef::Kind::Unit, 1));
    const QString before = shown("unitSignature");
    EXPECT_EQ(QStringLiteral("Pluto 01 ") + before, printed[1]);

    rs::project::Project edited = document()->project();
    const std::string code = rs::project::unitText(edited, 1);
    const auto read = rs::project::readUnitText(edited, 1, code + "Q1.3 = I1.0\n");
    ASSERT_TRUE(read.ok());
    document()->replace(QStringLiteral("typing"), read.project);
    EXPECT_NE(shown("unitSignature"), before);
}

// Issue 18: Project > Mark as Validated records the baseline as `validate`
// does, as one undo step, and the project page says who and when.
TEST_F(MainWindowTest, MarkAsValidatedRecordsTheBaselineAndThePageSaysSo) {
    ASSERT_TRUE(
        window.loadFile(QStringLiteral(RUNGSMITH_SOURCE_DIR "/resources/examples/press-line.sps"))
            .isEmpty());
    showWindow();
    ASSERT_TRUE(window.showPage(PageRef::Kind::Project, 0));
    auto* validated = window.findChild<QLabel*>(QStringLiteral("validatedLabel"));
    ASSERT_NE(validated, nullptr);
    EXPECT_TRUE(validated->text().startsWith(QStringLiteral("not yet")));
    DialogDriver driver({[](QDialog& dialog) {
        auto* by = dialog.findChild<QLineEdit*>(QStringLiteral("validatedBy"));
        ASSERT_NE(by, nullptr);
        by->setText(QStringLiteral("A. Reviewer"));
        dialog.findChild<QLineEdit*>(QStringLiteral("validationComment"))
            ->setText(QStringLiteral("FAT passed"));
        dialog.accept();
    }});
    action("markValidatedAction")->trigger();
    ASSERT_TRUE(driver.done());
    ASSERT_TRUE(document()->project().baseline.has_value());
    EXPECT_EQ(document()->project().baseline->by, "A. Reviewer");
    EXPECT_TRUE(projectText().contains(";@validated")) << projectText().toStdString();
    EXPECT_TRUE(validated->text().contains(QStringLiteral("A. Reviewer")));
    EXPECT_TRUE(validated->text().contains(QStringLiteral("FAT passed")));
    document()->undoStack()->undo();
    EXPECT_FALSE(document()->project().baseline.has_value());
}

} // namespace
