// SPDX-License-Identifier: GPL-3.0-or-later
// The project's properties in the IDE (docs/ide.md, "Properties"): the
// Properties node and page over the .prop file beside the project, its
// errors marked inline, completion, saving with the project, Prove All's
// rows, and a failed property's counterexample run in the simulator.
#include "WindowTest.h"

#include "document/ProjectDocument.h"
#include "ladder/LadderPage.h"
#include "project/VariableTable.h"
#include "prove/ProofResultsView.h"
#include "prove/PropertiesPage.h"
#include "prove/PropertyEditor.h"
#include "shell/ProjectTree.h"
#include "shell/StatusColors.h"
#include "sim/ScenarioResultsView.h"
#include "sim/SimulationMode.h"
#include "sim/WaveformPanel.h"

#include <QAction>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QProgressBar>
#include <QSignalSpy>
#include <QTest>
#include <QToolBar>

#include <gtest/gtest.h>

#include <optional>

namespace {

using rs::ui::PageRef;
using rs::ui::PropertyProof;

const QByteArray kPropertiesProject = "! id_pluto:00=000000000000\n! type_pluto:00=A20,is3\n"
                                      "! pgm_pluto:00\nS0.0_0\nQ0.2 = I0.12 * I0.0\n";
const QByteArray kProperties = "; the stop circuit\n"
                               "always Q0.2 -> I0.12   ; only with the stop circuit closed\n"
                               "never Q0.2\n";
constexpr int kProofMs = 60'000;

class PropertiesPageTest : public WindowTest {
protected:
    void SetUp() override {
        WindowTest::SetUp();
        propertiesPath = writeFile(QStringLiteral("line.prop"), kProperties);
        ASSERT_TRUE(
            window.loadFile(writeFile(QStringLiteral("line.sps"), kPropertiesProject)).isEmpty());
        showWindow();
    }

    rs::ui::PropertiesPage* page() { return window.propertiesPage(); }
    rs::ui::PropertyEditor* editor() { return page()->editor(); }
    rs::ui::ProofResultsView* results() { return page()->results(); }

    void showProperties() {
        clickNode({PageRef::Kind::Properties, document()});
        ASSERT_TRUE(page()->isVisible());
    }

    // Types the text as a user would replace it, then waits for the page to read it.
    void typeText(const QByteArray& text) {
        editor()->selectAll();
        editor()->removeSelectedText();
        editor()->insert(QString::fromUtf8(text));
        QTest::qWait(rs::ui::PropertiesPage::kReadDelayMs + 100);
    }

    bool proveAll() {
        action("proveAllAction")->trigger();
        return QTest::qWaitFor([this] { return !page()->isProving(); }, kProofMs);
    }

    QString resultOf(int row) {
        QTreeWidgetItem* item = results()->topLevelItem(row);
        return item ? item->text(rs::ui::ProofResultsView::ResultColumn) : QString();
    }

    QString propertiesPath;
};

TEST_F(PropertiesPageTest, TheProjectHasAPropertiesNodeWhosePageShowsThePropFileBesideIt) {
    rs::ui::ProjectTree* tree = window.projectTree();
    QTreeWidgetItem* node = tree->itemFor({PageRef::Kind::Properties, document()});
    ASSERT_NE(node, nullptr);
    EXPECT_EQ(node->text(0), QStringLiteral("Properties"));
    EXPECT_EQ(rs::ui::ProjectTree::pageOf(node->parent()).kind, PageRef::Kind::Project);
    showProperties();
    EXPECT_EQ(window.currentPage().kind, PageRef::Kind::Properties);
    EXPECT_EQ(editor()->textBytes(), kProperties);
    EXPECT_EQ(document()->propertiesPath(), QFileInfo(propertiesPath).absoluteFilePath());
    EXPECT_TRUE(page()->diagnostics().empty());
    EXPECT_FALSE(page()->findChild<QWidget*>(QStringLiteral("propertiesNote"))->isVisible());
    EXPECT_FALSE(document()->isModified());
}

TEST_F(PropertiesPageTest, ASyntaxErrorIsMarkedInlineAtItsLineAndColumn) {
    showProperties();
    typeText("always Q0.2 -> I0.12\n\nnever Q0.2 *\n");
    ASSERT_EQ(page()->diagnostics().size(), 1u);
    const rs::lang::Diagnostic& error = page()->diagnostics().front();
    EXPECT_EQ(error.line, 3);
    EXPECT_EQ(error.column, 13);
    // The margin's error mark and the message below the line, on line 3 only.
    EXPECT_TRUE(editor()->markersAtLine(2) & (1 << rs::ui::ProgramEditor::ErrorMarker));
    EXPECT_FALSE(editor()->markersAtLine(0) & (1 << rs::ui::ProgramEditor::ErrorMarker));
    EXPECT_EQ(editor()->annotation(2), QString::fromStdString(error.message));
    EXPECT_TRUE(editor()->annotation(0).isEmpty());

    // An operand the project does not have, on its line too; fixed, the marks go.
    typeText("never Q0.2\nalways Motor -> I0.12\n");
    ASSERT_EQ(page()->diagnostics().size(), 1u);
    EXPECT_EQ(page()->diagnostics().front().line, 2);
    EXPECT_EQ(page()->diagnostics().front().column, 8);
    EXPECT_TRUE(editor()->markersAtLine(1) & (1 << rs::ui::ProgramEditor::ErrorMarker));
    typeText("never Q0.2\nalways Q0.2 -> I0.12\n");
    EXPECT_TRUE(page()->diagnostics().empty());
    EXPECT_EQ(editor()->markersAtLine(1), 0u);

    // Prove All refuses a text with errors and says why.
    typeText("never Q0.2 *\n");
    EXPECT_FALSE(page()->proveAll({}));
    EXPECT_TRUE(page()->statusText().contains(QStringLiteral("error")));
}

TEST_F(PropertiesPageTest, CompletionOffersTheKeywordsAndTheProjectsOperands) {
    showProperties();
    EXPECT_EQ(editor()->completionsFor(QStringLiteral("alw")), QStringList{"always"});
    EXPECT_EQ(editor()->completionsFor(QStringLiteral("WI")), QStringList{"within"});
    const QStringList operands = editor()->completionsFor(QStringLiteral("i0."));
    EXPECT_TRUE(operands.contains(QStringLiteral("I0.12")));
    EXPECT_TRUE(operands.contains(QStringLiteral("I0.0")));
    EXPECT_TRUE(editor()->completionsFor(QStringLiteral("Q0")).contains(QStringLiteral("Q0.2")));

    // A name given on the Variables page is offered next.
    ASSERT_TRUE(document()->edit(QStringLiteral("Name"), [](rs::project::Project& project) {
        rs::project::setVariableName(project, rs::lang::readAddressWord("I0.12").address,
                                     "StopCircuit");
    }));
    EXPECT_EQ(editor()->completionsFor(QStringLiteral("stop")), QStringList{"StopCircuit"});

    // Typing a word's second letter opens the list, and Ctrl+Space after the first.
    typeText("");
    editor()->setFocus();
    QTest::keyClicks(editor(), QStringLiteral("ne"));
    EXPECT_TRUE(editor()->isListActive());
    editor()->cancelList();
    typeText("always ");
    editor()->setFocus();
    editor()->SendScintilla(QsciScintillaBase::SCI_DOCUMENTEND);
    QTest::keyClick(editor(), Qt::Key_Q);
    EXPECT_FALSE(editor()->isListActive());
    QTest::keyClick(editor(), Qt::Key_Space, Qt::ControlModifier);
    EXPECT_TRUE(editor()->isListActive());
}

TEST_F(PropertiesPageTest, ProveAllGivesARowPerPropertyProvedOrFailed) {
    showProperties();
    // One action, in the Build menu and on the page's tool bar.
    QAction* prove = action("proveAllAction");
    auto* build = window.menuBar()->findChild<QMenu*>(QStringLiteral("buildMenu"));
    ASSERT_NE(build, nullptr);
    EXPECT_TRUE(build->actions().contains(prove));
    EXPECT_TRUE(page()
                    ->findChild<QToolBar*>(QStringLiteral("propertiesToolBar"))
                    ->actions()
                    .contains(prove));

    QSignalSpy proving(page(), &rs::ui::PropertiesPage::provingChanged);
    ASSERT_TRUE(proveAll());
    EXPECT_EQ(proving.size(), 2);
    ASSERT_EQ(results()->topLevelItemCount(), 2);
    EXPECT_EQ(results()->topLevelItem(0)->text(rs::ui::ProofResultsView::LineColumn), "2");
    EXPECT_EQ(results()->topLevelItem(0)->text(rs::ui::ProofResultsView::PropertyColumn),
              "always Q0.2 -> I0.12");
    EXPECT_EQ(resultOf(0), QStringLiteral("proved"));
    EXPECT_EQ(results()->topLevelItem(1)->text(rs::ui::ProofResultsView::LineColumn), "3");
    EXPECT_EQ(resultOf(1), QStringLiteral("failed"));
    const PropertyProof* failed = results()->proofAt(1);
    ASSERT_NE(failed, nullptr);
    EXPECT_EQ(failed->status, PropertyProof::Status::Failed);
    EXPECT_GE(failed->depth, 1);
    EXPECT_TRUE(failed->scenario.contains(QStringLiteral("expect Q0.2 0")));
    EXPECT_EQ(
        results()->topLevelItem(1)->foreground(rs::ui::ProofResultsView::ResultColumn).color(),
        rs::ui::errorTextColor(results()->palette()));
    EXPECT_EQ(
        results()->topLevelItem(0)->foreground(rs::ui::ProofResultsView::ResultColumn).color(),
        rs::ui::passTextColor(results()->palette()));
    EXPECT_EQ(page()->statusText(), QStringLiteral("1 proved, 1 failed, 0 unknown"));

    // The failed row is chosen; Open Counterexample is for it only. A double-click goes to
    // its line.
    EXPECT_EQ(results()->currentItem(), results()->topLevelItem(1));
    EXPECT_TRUE(page()->openCounterexampleAction()->isEnabled());
    results()->setCurrentItem(results()->topLevelItem(0));
    EXPECT_FALSE(page()->openCounterexampleAction()->isEnabled());
    results()->setCurrentItem(results()->topLevelItem(1));
    EXPECT_TRUE(page()->openCounterexampleAction()->isEnabled());
    emit results()->itemActivated(results()->topLevelItem(1), 0);
    int line = -1;
    int index = -1;
    editor()->getCursorPosition(&line, &index);
    EXPECT_EQ(line, 2);
}

TEST_F(PropertiesPageTest, ProgressCountsThePropertiesAndCancelStopsTheRun) {
    showProperties();
    QSignalSpy proving(page(), &rs::ui::PropertiesPage::provingChanged);
    action("proveAllAction")->trigger();
    EXPECT_TRUE(page()->isProving());
    auto* bar = page()->findChild<QProgressBar*>(QStringLiteral("proofProgress"));
    ASSERT_NE(bar, nullptr);
    // The tool bar shows the bar through its action.
    auto* toolBar = page()->findChild<QToolBar*>(QStringLiteral("propertiesToolBar"));
    QAction* barShown = nullptr;
    for (QAction* shown : toolBar->actions())
        if (toolBar->widgetForAction(shown) == bar)
            barShown = shown;
    ASSERT_NE(barShown, nullptr);
    EXPECT_TRUE(barShown->isVisible());
    EXPECT_EQ(bar->maximum(), 2); // two properties; the assumption-free file has no other
    EXPECT_EQ(page()->statusText(), QStringLiteral("Compiling line.sps..."));
    EXPECT_TRUE(page()->cancelAction()->isEnabled());
    EXPECT_FALSE(action("proveAllAction")->isEnabled());

    // What was not proved when Cancel came says so; the window can prove again.
    page()->cancelAction()->trigger();
    ASSERT_TRUE(QTest::qWaitFor([this] { return !page()->isProving(); }, kProofMs));
    EXPECT_EQ(proving.size(), 2);
    EXPECT_FALSE(barShown->isVisible());
    EXPECT_TRUE(page()->statusText().startsWith(QStringLiteral("Cancelled: ")))
        << page()->statusText().toStdString();
    for (int row = 0; row < 2; ++row)
        EXPECT_TRUE(resultOf(row) == QStringLiteral("not proved") || results()->proofAt(row))
            << resultOf(row).toStdString();
    EXPECT_FALSE(page()->cancelAction()->isEnabled());
    EXPECT_TRUE(action("proveAllAction")->isEnabled());
    ASSERT_TRUE(proveAll());
    EXPECT_EQ(resultOf(0), QStringLiteral("proved"));
    EXPECT_EQ(resultOf(1), QStringLiteral("failed"));
}

TEST_F(PropertiesPageTest, AnotherProjectsPropertiesCancelAProofAndShowNoneOfItsRows) {
    showProperties();
    rs::ui::ProjectDocument* first = document();
    ASSERT_TRUE(
        window.loadFile(writeFile(QStringLiteral("other.sps"), kPropertiesProject)).isEmpty());
    ASSERT_NE(window.documents().back(), first);
    ASSERT_TRUE(window.showPage({PageRef::Kind::Properties, first}));
    action("proveAllAction")->trigger();
    ASSERT_TRUE(page()->isProving());
    ASSERT_TRUE(window.showPage({PageRef::Kind::Properties, window.documents().back()}));
    ASSERT_TRUE(QTest::qWaitFor([this] { return !page()->isProving(); }, kProofMs));
    EXPECT_EQ(page()->document(), window.documents().back());
    EXPECT_EQ(results()->topLevelItemCount(), 0);
    EXPECT_TRUE(page()->statusText().isEmpty()) << page()->statusText().toStdString();
    EXPECT_TRUE(action("proveAllAction")->isEnabled());
}

TEST_F(PropertiesPageTest, SavingTheProjectWritesThePropertiesBesideIt) {
    showProperties();
    const QByteArray changed = "never Q0.2 * /I0.12\n";
    typeText(changed);
    EXPECT_TRUE(document()->isModified());
    EXPECT_TRUE(window.isWindowModified());
    EXPECT_EQ(readFile(propertiesPath), kProperties);
    action("saveAction")->trigger();
    EXPECT_FALSE(document()->isModified());
    EXPECT_EQ(readFile(propertiesPath), changed);
    // Undo is the editor's, and marks the project modified again.
    action("undoAction")->trigger();
    EXPECT_NE(editor()->textBytes(), changed);
    EXPECT_TRUE(document()->isModified());
}

TEST_F(PropertiesPageTest, AProjectWithoutPropertiesShowsWhatToWriteAndSavesNoEmptyFile) {
    const QString other = writeFile(QStringLiteral("other.sps"), kPropertiesProject);
    ASSERT_TRUE(window.loadFile(other).isEmpty());
    ASSERT_TRUE(window.showPage(PageRef::Kind::Properties, -1));
    EXPECT_TRUE(editor()->textBytes().isEmpty());
    EXPECT_TRUE(page()->findChild<QWidget*>(QStringLiteral("propertiesNote"))->isVisible());
    EXPECT_TRUE(page()->diagnostics().empty());
    action("saveAction")->trigger();
    EXPECT_FALSE(QFileInfo::exists(directory.filePath(QStringLiteral("other.prop"))));

    // The example is all comments: still nothing to prove, and nothing marked.
    QTest::mouseClick(page()->findChild<QWidget*>(QStringLiteral("insertExampleButton")),
                      Qt::LeftButton);
    QTest::qWait(rs::ui::PropertiesPage::kReadDelayMs + 100);
    EXPECT_EQ(editor()->textBytes(), rs::ui::PropertiesPage::example().toUtf8());
    EXPECT_TRUE(page()->diagnostics().empty());
    EXPECT_FALSE(page()->proveAll({}));
    typeText("cover Q0.2\n");
    EXPECT_FALSE(page()->findChild<QWidget*>(QStringLiteral("propertiesNote"))->isVisible());
    action("saveAction")->trigger();
    EXPECT_EQ(readFile(directory.filePath(QStringLiteral("other.prop"))), "cover Q0.2\n");
}

TEST_F(PropertiesPageTest, OpenCounterexampleRunsItInTheSimulatorFailingOnItsLastLine) {
    showProperties();
    ASSERT_TRUE(proveAll());
    results()->setCurrentItem(results()->topLevelItem(1));
    rs::ui::SimulationSession* session = window.simulation()->session();
    std::optional<rs::ui::SimulationSession::ScenarioResult> finished;
    QObject::connect(
        session, &rs::ui::SimulationSession::scenarioFinished, session,
        [&](const rs::ui::SimulationSession::ScenarioResult& result) { finished = result; });
    page()->openCounterexampleAction()->trigger();
    ASSERT_TRUE(QTest::qWaitFor([&] { return finished.has_value(); }, 10'000));

    // Beside the project, named as rungsmith-cli prove names it.
    const QString scenario = directory.filePath(QStringLiteral("line-3.scn"));
    EXPECT_EQ(QFileInfo(finished->path).absoluteFilePath(), QFileInfo(scenario).absoluteFilePath());
    const QByteArray text = readFile(scenario);
    EXPECT_EQ(text, results()->proofAt(1)->scenario.toUtf8());
    EXPECT_EQ(finished->failed, 1);
    ASSERT_EQ(finished->failures.size(), 1u);
    EXPECT_EQ(finished->failures.front().line, text.count('\n'));

    // Stopped after the scan that breaks the property, with its waveform.
    EXPECT_EQ(session->state(), rs::ui::SimulationSession::State::Stopped);
    const rs::lang::Address q02 = rs::lang::readAddressWord("Q0.2").address;
    EXPECT_EQ(session->simulation()->value(q02), 1);
    EXPECT_TRUE(session->recorder().contains(q02));
    EXPECT_TRUE(window.simulation()->waveformPanel()->isVisible());

    // The ladder shows, live, Q0.2 chosen and why it is on.
    EXPECT_EQ(window.currentPage().kind, PageRef::Kind::Ladder);
    rs::ui::LadderPage* ladder = window.ladderPage();
    EXPECT_TRUE(ladder->isLive());
    EXPECT_TRUE(ladder->outputExplanation().startsWith(QStringLiteral("Q0.2 is on")))
        << ladder->outputExplanation().toStdString();
}

} // namespace
