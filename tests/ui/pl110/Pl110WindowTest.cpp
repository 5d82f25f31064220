// SPDX-License-Identifier: GPL-3.0-or-later
#include "pl110/Pl110Window.h"
#include "pl110/Pl110Document.h"
#include "pl110/Pl110LadderView.h"
#include "pl110/Pl110NamesPage.h"
#include "pl110/Pl110Simulation.h"
#include "pl110/Pl110WaveformPanel.h"
#include "pl110/ProgramText.h"
#include "pl110/Rungs.h"
#include "text/ProgramEditor.h"

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPointer>
#include <QProcess>
#include <QPushButton>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include "DialogDriver.h"
#include "QtPrinting.h"

#include <gtest/gtest.h>

#include <memory>

// The PL110 window as a user drives it: the example opens on its ladder,
// typing, naming and CSV change the one text with one undo history, the
// simulator runs what is shown and is driven from the ladder, scenarios and
// saving work, and nothing is lost when a change cannot be made.

namespace {

using rs::ui::Pl110Document;
using rs::ui::Pl110Window;

const QString kFillingStation =
    QStringLiteral(RUNGSMITH_SOURCE_DIR "/resources/examples/pl110/filling-station.sps");
const QString kFillingScenario =
    QStringLiteral(RUNGSMITH_SOURCE_DIR "/resources/examples/pl110/filling-station.scn");

rs::pl110::Address pl110Address(const char* text) {
    return rs::pl110::readAddress(text).address;
}

class Pl110WindowTest : public ::testing::Test {
protected:
    void SetUp() override { open(kFillingStation); }

    void open(const QString& path) {
        QString error;
        Pl110Document* document = Pl110Document::open(path, error);
        ASSERT_NE(document, nullptr) << error.toStdString();
        window = std::make_unique<Pl110Window>(document);
        window->setAttribute(Qt::WA_DeleteOnClose, false);
    }
    Pl110Document* document() const { return window->document(); }
    QAction* action(const char* name) const {
        auto* found = window->findChild<QAction*>(QString::fromLatin1(name));
        EXPECT_NE(found, nullptr) << name;
        return found;
    }
    rs::ui::ProgramEditor* editor() const {
        return window->findChild<rs::ui::ProgramEditor*>(QStringLiteral("pl110Editor"));
    }
    rs::ui::Pl110LadderView* ladder() const {
        return window->findChild<rs::ui::Pl110LadderView*>(QStringLiteral("pl110LadderView"));
    }
    QTableWidget* names() const {
        return window->findChild<QTableWidget*>(QStringLiteral("pl110NamesTable"));
    }
    QListWidget* problems() const {
        return window->findChild<QListWidget*>(QStringLiteral("pl110Problems"));
    }
    // Types a whole new text, as a burst of typing the window takes in after a pause.
    void type(const QByteArray& text) {
        editor()->setText(QString::fromUtf8(text));
        window->applyTyping();
    }
    int namesRow(const QString& address) const {
        for (int row = 0; row < names()->rowCount(); ++row)
            if (names()->item(row, 0)->text() == address)
                return row;
        return -1;
    }
    QString writeFile(const QString& name, const QByteArray& bytes) {
        QFile file(directory.filePath(name));
        EXPECT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(bytes);
        return file.fileName();
    }

    QTemporaryDir directory;
    std::unique_ptr<Pl110Window> window;
};

TEST_F(Pl110WindowTest, TheExampleOpensOnItsLadderWithEveryRungAndNoProblems) {
    const auto* pages = window->findChild<QTabWidget*>(QStringLiteral("pl110Pages"));
    EXPECT_EQ(pages->currentWidget(), ladder());
    EXPECT_EQ(ladder()->rungCount(), 9);
    EXPECT_EQ(problems()->count(), 0);
    EXPECT_TRUE(action("pl110StartAction")->isEnabled());
    EXPECT_FALSE(window->isWindowModified());
    EXPECT_TRUE(window->windowTitle().contains(QStringLiteral("filling-station.sps")));
}

TEST_F(Pl110WindowTest, TypingChangesTheLadderAndUndoesAsOneStepOfTheOneHistory) {
    const QByteArray before = document()->text();
    type(before + "Q4 = I6\n");
    EXPECT_EQ(ladder()->rungCount(), 10);
    EXPECT_TRUE(window->isWindowModified());
    action("pl110UndoAction")->trigger();
    EXPECT_EQ(document()->text(), before);
    EXPECT_EQ(editor()->textBytes(), before);
    EXPECT_EQ(ladder()->rungCount(), 9);
    EXPECT_FALSE(window->isWindowModified());
    action("pl110RedoAction")->trigger();
    EXPECT_EQ(ladder()->rungCount(), 10);
}

TEST_F(Pl110WindowTest, ErrorsAreListedAtTheirLineAndColumnAndStopTheSimulator) {
    type(document()->text() + "Q4 = I0\n");
    ASSERT_EQ(problems()->count(), 1);
    const QString problem = problems()->item(0)->text();
    EXPECT_TRUE(problem.startsWith(QStringLiteral("30:6: "))) << problem.toStdString();
    EXPECT_TRUE(problem.contains(QStringLiteral("I0 is out of range"))) << problem.toStdString();
    EXPECT_FALSE(action("pl110StartAction")->isEnabled());
    // The ladder still shows every line that reads.
    EXPECT_EQ(ladder()->rungCount(), 9);
}

TEST_F(Pl110WindowTest, RenamingOnTheNamesPageFollowsIntoTheRungsAndUndoes) {
    const QByteArray before = document()->text();
    const int row = namesRow(QStringLiteral("I1"));
    ASSERT_GE(row, 0);
    names()->item(row, 1)->setText(QStringLiteral("StartButton"));
    const QString text = QString::fromUtf8(document()->text());
    EXPECT_TRUE(text.contains(QStringLiteral("! I1=StartButton"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("Running = StartButton * Stop")))
        << text.toStdString();
    EXPECT_EQ(editor()->textBytes(), document()->text());
    action("pl110UndoAction")->trigger();
    EXPECT_EQ(document()->text(), before);
}

TEST_F(Pl110WindowTest, TheLastRowNamesAnotherAddressAndABadNameIsRefusedWithItsReason) {
    const int last = names()->rowCount() - 1;
    names()->item(last, 0)->setText(QStringLiteral("I6"));
    names()->item(last, 1)->setText(QStringLiteral("Door"));
    EXPECT_TRUE(QString::fromUtf8(document()->text()).contains(QStringLiteral("! I6=Door")));

    const QByteArray before = document()->text();
    names()->item(namesRow(QStringLiteral("Q1")), 1)->setText(QStringLiteral("Stop"));
    EXPECT_EQ(document()->text(), before);
    const auto* problem = window->findChild<QLabel*>(QStringLiteral("pl110NamesProblem"));
    EXPECT_FALSE(problem->isHidden());
    EXPECT_TRUE(problem->text().contains(QStringLiteral("already names another address")))
        << problem->text().toStdString();
}

TEST_F(Pl110WindowTest, NamesAreNotRewrittenWhileALineDoesNotRead) {
    type(document()->text() + "Q4 = = I1\n");
    const QByteArray before = document()->text();
    names()->item(namesRow(QStringLiteral("I1")), 1)->setText(QStringLiteral("Go"));
    // Printing the program would drop the line that does not read.
    EXPECT_EQ(document()->text(), before);
}

TEST_F(Pl110WindowTest, NamesGoOutAndComeBackAsCsvAndABadFileChangesNothing) {
    auto* page = window->findChild<rs::ui::Pl110NamesPage*>(QStringLiteral("pl110NamesPage"));
    const QString csv = directory.filePath(QStringLiteral("names.csv"));
    ASSERT_TRUE(page->exportCsv(csv, ';').isEmpty());
    QFile file(csv);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray exported = file.readAll();
    EXPECT_TRUE(exported.contains("I1;Start;green button, N.O.")) << exported.toStdString();

    page->importCsv(writeFile(QStringLiteral("renamed.csv"), "Variable,Symbolic Name\nI1,Go\n"));
    EXPECT_TRUE(QString::fromUtf8(document()->text()).contains(QStringLiteral("Running = Go *")));

    const QByteArray before = document()->text();
    page->importCsv(writeFile(QStringLiteral("bad.csv"), "I2,Halt\nX9,Nothing\n"));
    EXPECT_EQ(document()->text(), before);
    const auto* problem = window->findChild<QLabel*>(QStringLiteral("pl110NamesProblem"));
    EXPECT_TRUE(problem->text().contains(QStringLiteral("bad.csv:2:1:")))
        << problem->text().toStdString();
}

TEST_F(Pl110WindowTest, ClickingAnInputsContactSwitchesItAndTheRungRunsOnIt) {
    rs::ui::Pl110Simulation* simulation = window->simulation();
    ladder()->resize(1000, 800);
    simulation->set(pl110Address("I2"), 1); // Stop is N.C.: 1 while not pressed
    ASSERT_TRUE(simulation->singleScan().isEmpty());
    EXPECT_EQ(simulation->engine()->value(pl110Address("M1")), 0);
    // The ladder's contact of Start, as a click on it reports it.
    Q_EMIT ladder()->operandClicked(QStringLiteral("I1"));
    EXPECT_EQ(simulation->engine()->value(pl110Address("I1")), 1);
    ASSERT_TRUE(simulation->singleScan().isEmpty());
    EXPECT_EQ(simulation->engine()->value(pl110Address("M1")), 1);
    Q_EMIT ladder()->operandClicked(QStringLiteral("I1"));
    ASSERT_TRUE(simulation->singleScan().isEmpty());
    EXPECT_EQ(simulation->engine()->value(pl110Address("M1")), 1) << "Running holds itself";
    // A marker is forced, and stays so against the program.
    Q_EMIT ladder()->operandClicked(QStringLiteral("M1"));
    EXPECT_TRUE(simulation->isForced(pl110Address("M1")));
    ASSERT_TRUE(simulation->singleScan().isEmpty());
    EXPECT_EQ(simulation->engine()->value(pl110Address("M1")), 0);
}

TEST_F(Pl110WindowTest, AValueTypedOnTheNamesPageSetsAnInputWhileSimulating) {
    rs::ui::Pl110Simulation* simulation = window->simulation();
    QTableWidgetItem* stop = names()->item(namesRow(QStringLiteral("I2")), 3);
    stop->setText(QStringLiteral("1")); // not simulating: nothing to set
    EXPECT_FALSE(simulation->isForced(pl110Address("I2")));
    ASSERT_TRUE(simulation->singleScan().isEmpty());
    QTest::qWait(120); // the live pages' next refresh
    stop->setText(QStringLiteral("1"));
    EXPECT_EQ(simulation->engine()->value(pl110Address("I2")), 1);
    QTest::qWait(120);
    EXPECT_EQ(stop->text(), QStringLiteral("1"));
}

TEST_F(Pl110WindowTest, AChangedProgramStopsTheSimulationItRan) {
    rs::ui::Pl110Simulation* simulation = window->simulation();
    ASSERT_TRUE(simulation->start().isEmpty());
    EXPECT_TRUE(simulation->isRunning());
    EXPECT_FALSE(action("pl110StartAction")->isEnabled());
    type(document()->text() + "Q4 = I6\n");
    EXPECT_FALSE(simulation->isRunning());
    EXPECT_EQ(simulation->engine(), nullptr);
    EXPECT_TRUE(action("pl110StartAction")->isEnabled());
}

TEST_F(Pl110WindowTest, AScenarioRunsToItsEndAndItsResultsAreShown) {
    ASSERT_TRUE(window->runScenario(kFillingScenario).isEmpty());
    const auto* output = window->findChild<QPlainTextEdit*>(QStringLiteral("pl110ScenarioOutput"));
    EXPECT_TRUE(output->toPlainText().contains(QStringLiteral("7 passed, 0 failed")))
        << output->toPlainText().toStdString();
    ASSERT_NE(window->simulation()->engine(), nullptr);
    EXPECT_EQ(window->simulation()->engine()->value(pl110Address("VW10")), 2);

    const QString failing = writeFile(QStringLiteral("wrong.scn"), "expect Pump 1\n");
    ASSERT_TRUE(window->runScenario(failing).isEmpty());
    EXPECT_TRUE(output->toPlainText().contains(QStringLiteral("wrong.scn:1: expect Pump 1 failed")))
        << output->toPlainText().toStdString();
}

TEST_F(Pl110WindowTest, TheWaveformRecordsTheNamedVariablesScanByScanAndExportsThem) {
    const rs::pl110::WaveformRecorder& recorder = window->simulation()->recorder();
    EXPECT_EQ(recorder.rows(), 12u); // every declared name
    auto* panel = window->findChild<rs::ui::Pl110WaveformPanel*>();
    ASSERT_NE(panel, nullptr);
    EXPECT_EQ(panel->add(QStringLiteral("T1")), QStringLiteral("T1 is plotted already"));
    EXPECT_TRUE(panel->add(QStringLiteral("Nowhere")).contains(QStringLiteral("Nowhere")));
    EXPECT_TRUE(panel->add(QStringLiteral("SM0.1")).isEmpty());
    ASSERT_TRUE(window->runScenario(kFillingScenario).isEmpty());
    EXPECT_EQ(recorder.startMs(), 0);
    EXPECT_EQ(recorder.endMs(), window->simulation()->engine()->timeMs());
    // The pump went on and off twice: four changes after power on.
    const auto pump =
        std::find_if(recorder.traces().begin(), recorder.traces().end(),
                     [](const auto& trace) { return trace.address == pl110Address("Q1"); });
    ASSERT_NE(pump, recorder.traces().end());
    EXPECT_EQ(pump->changes.size(), 5u);
    const QString vcd = directory.filePath(QStringLiteral("run.vcd"));
    ASSERT_TRUE(panel->exportVcd(vcd).isEmpty());
    QFile file(vcd);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray text = file.readAll();
    EXPECT_TRUE(text.contains("$scope module pl110 $end")) << text.toStdString();
    EXPECT_TRUE(text.contains(" Q1 $end")) << text.toStdString();
}

// mbpoll once over RTU, the window's event loop answering meanwhile: -0
// makes -r the datasheet's address; values after the device are written.
QString pollRtu(const QString& device, const QStringList& arguments,
                const QStringList& values = {}) {
    QProcess mbpoll;
    mbpoll.start(QStringLiteral("mbpoll"),
                 QStringList{QStringLiteral("-m"), QStringLiteral("rtu"), QStringLiteral("-b"),
                             QStringLiteral("19200"), QStringLiteral("-P"), QStringLiteral("none"),
                             QStringLiteral("-a"), QStringLiteral("1"), QStringLiteral("-0"),
                             QStringLiteral("-1"), QStringLiteral("-o"), QStringLiteral("2")} +
                     arguments + QStringList{device} + values);
    QElapsedTimer waited;
    waited.start();
    while (mbpoll.state() != QProcess::NotRunning && waited.elapsed() < 10000)
        QTest::qWait(10);
    EXPECT_EQ(mbpoll.state(), QProcess::NotRunning);
    return QString::fromUtf8(mbpoll.readAllStandardOutput() + mbpoll.readAllStandardError());
}

TEST_F(Pl110WindowTest, AModbusClientReadsAndWritesTheSimulatedMemoryOverRtu) {
    if (QStandardPaths::findExecutable(QStringLiteral("mbpoll")).isEmpty())
        GTEST_SKIP() << "mbpoll is not installed (scripts/dev installs it)";
    rs::ui::Pl110Simulation* simulation = window->simulation();
    action("pl110ServeModbusAction")->trigger();
    const QString device = simulation->modbusDevice();
    ASSERT_FALSE(device.isEmpty());
    EXPECT_TRUE(
        window->findChild<QLabel*>(QStringLiteral("pl110ModbusDevice"))->text().contains(device));
    simulation->set(pl110Address("I2"), 1);
    simulation->set(pl110Address("I1"), 1);
    ASSERT_TRUE(simulation->singleScan().isEmpty()); // Running (M1) comes on
    // M1 is coil 4000; VW20 is holding register 2020.
    const QString coils =
        pollRtu(device, {QStringLiteral("-t"), QStringLiteral("0"), QStringLiteral("-r"),
                         QStringLiteral("4000"), QStringLiteral("-c"), QStringLiteral("2")});
    EXPECT_TRUE(coils.contains(QStringLiteral("[4000]: \t1"))) << coils.toStdString();
    EXPECT_TRUE(coils.contains(QStringLiteral("[4001]: \t0"))) << coils.toStdString();
    const QString written = pollRtu(
        device,
        {QStringLiteral("-t"), QStringLiteral("4"), QStringLiteral("-r"), QStringLiteral("2020")},
        {QStringLiteral("1234")});
    EXPECT_TRUE(written.contains(QStringLiteral("Written 1 references"))) << written.toStdString();
    EXPECT_EQ(simulation->engine()->value(pl110Address("VW20")), 1234);
    action("pl110ServeModbusAction")->trigger();
    EXPECT_TRUE(simulation->modbusDevice().isEmpty());
}

TEST_F(Pl110WindowTest, SavingWritesTheTextAndAFailedSaveKeepsTheFileAndTheChanges) {
    const QString path = directory.filePath(QStringLiteral("station.sps"));
    ASSERT_TRUE(document()->saveAs(path).isEmpty());
    type(document()->text() + "Q4 = I6\n");
    EXPECT_TRUE(window->isWindowModified());
    action("pl110SaveAction")->trigger();
    EXPECT_FALSE(window->isWindowModified());
    QFile saved(path);
    ASSERT_TRUE(saved.open(QIODevice::ReadOnly));
    EXPECT_EQ(saved.readAll(), document()->text());

    EXPECT_FALSE(
        document()->saveAs(directory.filePath(QStringLiteral("no/such/dir.sps"))).isEmpty());
    EXPECT_EQ(document()->path(), path);
}

// Types into the line dialog that opens next and presses Enter; what the
// dialog said about the text as it was typed.
struct LineAnswer {
    QString typed;
    QString shown;   // the dialog's text when it opened
    QString problem; // its message for what was typed
    bool okEnabled = false;
};

DialogDriver::Handler answerLine(LineAnswer& answer) {
    return [&answer](QDialog& dialog) {
        auto* line = dialog.findChild<QLineEdit*>(QStringLiteral("pl110LineEdit"));
        answer.shown = line->text();
        line->setText(answer.typed);
        answer.problem = dialog.findChild<QLabel*>(QStringLiteral("pl110LineProblem"))->text();
        auto* ok = dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
        answer.okEnabled = ok->isEnabled();
        if (answer.okEnabled)
            dialog.accept();
        else
            dialog.reject();
    };
}

class Pl110LadderEditing : public Pl110WindowTest {
protected:
    void SetUp() override {
        Pl110WindowTest::SetUp();
        window->show();
        ladder()->setFocus();
        QApplication::setActiveWindow(window.get());
    }
    void key(Qt::Key key, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
        QTest::keyClick(ladder(), key, modifiers);
    }
    // Presses a key that opens a line dialog and answers it with `typed`.
    LineAnswer keyIntoDialog(Qt::Key pressed, const QString& typed) {
        LineAnswer answer{typed, {}, {}, false};
        DialogDriver driver({answerLine(answer)});
        key(pressed);
        EXPECT_TRUE(driver.done());
        // As a window manager does when a dialog closes.
        QApplication::setActiveWindow(window.get());
        return answer;
    }
    QString rungLine(int number) const {
        const auto rungs = rs::pl110::numberedRungs(document()->program());
        return QString::fromStdString(
            rs::pl110::printRungLine(*rungs.at(static_cast<std::size_t>(number - 1)).line));
    }
};

TEST_F(Pl110LadderEditing, TheKeyboardWritesANewRungAfterTheSelectedOne) {
    ladder()->select(2);
    const LineAnswer answer = keyIntoDialog(Qt::Key_Insert, QStringLiteral("Q4 = Start * /I6"));
    EXPECT_TRUE(answer.okEnabled) << answer.problem.toStdString();
    EXPECT_EQ(ladder()->rungCount(), 10);
    EXPECT_EQ(rungLine(3), QStringLiteral("Q4 = Start * /I6"));
    EXPECT_EQ(ladder()->selectedRung(), 3);
    action("pl110UndoAction")->trigger();
    EXPECT_EQ(ladder()->rungCount(), 9);
}

TEST_F(Pl110LadderEditing, ShiftInsertWritesARungAtTheEndOfInit) {
    ladder()->select(5); // in MAIN
    LineAnswer answer{QStringLiteral("(VW20 = 7)"), {}, {}, false};
    DialogDriver driver({answerLine(answer)});
    key(Qt::Key_Insert, Qt::ShiftModifier);
    ASSERT_TRUE(driver.done());
    EXPECT_EQ(rungLine(2), QStringLiteral("(VW20 = 7)"));
    const auto rungs = rs::pl110::numberedRungs(document()->program());
    EXPECT_TRUE(rungs[1].init);
    EXPECT_EQ(ladder()->selectedRung(), 2);
}

TEST_F(Pl110LadderEditing, TextThatDoesNotReadIsRefusedInTheDialogWithItsColumn) {
    ladder()->select(2);
    const QByteArray before = document()->text();
    const LineAnswer answer = keyIntoDialog(Qt::Key_Insert, QStringLiteral("Q4 = Nowhere"));
    EXPECT_FALSE(answer.okEnabled);
    EXPECT_TRUE(answer.problem.contains(QStringLiteral("Column 6")))
        << answer.problem.toStdString();
    EXPECT_EQ(document()->text(), before);
}

TEST_F(Pl110LadderEditing, ArrowsSelectAContactWhichEnterEditsAndDeleteRemoves) {
    ladder()->select(3); // Pump = Running * CanPresent * /Full * /BatchDone
    for (int i = 0; i < 10; ++i)
        key(Qt::Key_Left);
    ASSERT_NE(ladder()->selectedElement(), nullptr);
    EXPECT_EQ(ladder()->selectedElement()->name, QStringLiteral("Running"));
    key(Qt::Key_Right);
    EXPECT_EQ(ladder()->selectedElement()->name, QStringLiteral("CanPresent"));
    const LineAnswer answer = keyIntoDialog(Qt::Key_Return, QStringLiteral("/CanPresent"));
    EXPECT_EQ(answer.shown, QStringLiteral("CanPresent"));
    EXPECT_EQ(rungLine(3), QStringLiteral("Pump = Running * /CanPresent * /Full * /BatchDone"));
    key(Qt::Key_Delete);
    EXPECT_EQ(rungLine(3), QStringLiteral("Pump = Running * /Full * /BatchDone"));
    ASSERT_NE(ladder()->selectedElement(), nullptr);
    EXPECT_EQ(ladder()->selectedElement()->name, QStringLiteral("Full"));
    keyIntoDialog(Qt::Key_Backslash, QStringLiteral("M2"));
    EXPECT_EQ(rungLine(3), QStringLiteral("Pump = Running * (/Full + M2) * /BatchDone"));
    keyIntoDialog(Qt::Key_BracketLeft, QStringLiteral("I7"));
    EXPECT_TRUE(rungLine(3).startsWith(QStringLiteral("Pump = Running * ")))
        << rungLine(3).toStdString();
    EXPECT_EQ(document()->undoStack()->count(), 4);
}

TEST_F(Pl110LadderEditing, RungsMoveWithTheirCommentsAndTheOutputsDeleteRemovesTheRung) {
    ladder()->select(4); // TON(Overrun, ...) with its comment above
    key(Qt::Key_Up, Qt::ControlModifier);
    EXPECT_EQ(ladder()->selectedRung(), 3);
    EXPECT_TRUE(rungLine(3).startsWith(QStringLiteral("TON(Overrun"))) << rungLine(3).toStdString();
    const QString text = QString::fromUtf8(document()->text());
    EXPECT_LT(text.indexOf(QStringLiteral("; A can that is not full")),
              text.indexOf(QStringLiteral("TON(Overrun")));
    EXPECT_LT(text.indexOf(QStringLiteral("TON(Overrun")), text.indexOf(QStringLiteral("Pump = ")));
    ladder()->select(3); // its output
    key(Qt::Key_Delete);
    EXPECT_EQ(ladder()->rungCount(), 8);
    EXPECT_FALSE(
        QString::fromUtf8(document()->text()).contains(QStringLiteral("; A can that is not full")));
}

TEST_F(Pl110LadderEditing, F6GoesToTheSelectedRungsLineAndBack) {
    ladder()->select(5);
    action("pl110LadderOrTextAction")->trigger();
    int line = 0;
    int index = 0;
    editor()->getCursorPosition(&line, &index);
    EXPECT_EQ(line + 1, 24);            // Alarm = Overrun + ...
    editor()->setCursorPosition(20, 0); // Pump = ...
    action("pl110LadderOrTextAction")->trigger();
    EXPECT_EQ(ladder()->selectedRung(), 3);
}

TEST_F(Pl110LadderEditing, SpaceSwitchesTheSelectedInputWhileSimulating) {
    ASSERT_TRUE(window->simulation()->singleScan().isEmpty());
    ladder()->select(2); // Running = Start * Stop * /Alarm + ...
    for (int i = 0; i < 10; ++i)
        key(Qt::Key_Left);
    ASSERT_EQ(ladder()->selectedElement()->address, QStringLiteral("I1"));
    key(Qt::Key_Space);
    EXPECT_EQ(window->simulation()->engine()->value(pl110Address("I1")), 1);
}

TEST(Pl110NewProgram, ANewProgramRunsAsItStands) {
    const QPointer<Pl110Window> window = Pl110Window::newWindow(QStringLiteral("Press"));
    ASSERT_TRUE(window);
    EXPECT_TRUE(window->document()->isRunnable());
    EXPECT_TRUE(window->document()->text().contains("$name Press"));
    EXPECT_TRUE(window->windowTitle().startsWith(QStringLiteral("Press")));
    window->document()->undoStack()->setClean();
    delete window.data();
}

TEST(Pl110Document, AFileThatIsNotAPl110ProgramIsRefusedWithTheReason) {
    QString error;
    EXPECT_EQ(
        Pl110Document::open(QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps"), error),
        nullptr);
    EXPECT_TRUE(error.contains(QStringLiteral("$target PL110"))) << error.toStdString();
}

} // namespace
