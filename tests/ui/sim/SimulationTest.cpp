// SPDX-License-Identifier: GPL-3.0-or-later
#include "DiagnosticsText.h"
#include "WindowTest.h"

#include "document/ProjectDocument.h"
#include "ladder/LadderDrawing.h"
#include "ladder/LadderPage.h"
#include "ladder/LadderView.h"
#include "ladder/NetworkItem.h"
#include "pages/VariableTableModel.h"
#include "pages/VariablesPage.h"
#include "sim/BusStatusView.h"
#include "sim/ForcesView.h"
#include "sim/LiveLadder.h"
#include "sim/ScenarioFileViewer.h"
#include "sim/ScenarioResultsView.h"
#include "sim/SimulationControls.h"
#include "sim/SimulationMode.h"
#include "sim/WatchView.h"
#include "sim/WaveformPanel.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QContextMenuEvent>
#include <QDockWidget>
#include <QHeaderView>
#include <QImage>
#include <QLabel>
#include <QMenu>
#include <QProcess>
#include <QPushButton>
#include <QTabBar>
#include <QTableView>
#include <QTableWidget>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <QTreeWidget>

#include <gtest/gtest.h>

using namespace rs;
using rs::test::addressOf;
using rs::ui::PageRef;

namespace {

class SimulationTest : public WindowTest {
protected:
    void SetUp() override {
        WindowTest::SetUp();
        window.showExample();
        showWindow();
        ASSERT_TRUE(window.showPage(PageRef{PageRef::Kind::Ladder, document(), 0, 0}));
        mode()->session()->setUpdateInterval(1);
    }

    ui::SimulationMode* mode() { return window.simulation(); }
    ui::SimulationSession* session() { return mode()->session(); }
    ui::LadderPage* ladder() { return window.ladderPage(); }
    const sim::Simulation& simulation() { return *session()->simulation(); }

    void begin() {
        action("simulateAction")->trigger();
        ASSERT_TRUE(session()->isActive());
        ASSERT_TRUE(ladder()->isLive());
    }

    // The first element on the shown ladder page with this operand.
    const ladder::ElementLayout* find(const QString& address, ui::NetworkItem** owner) {
        for (int step = 0; step < ladder()->stepCount(); ++step)
            for (int network = 0; network < ladder()->networkCount(step); ++network) {
                ui::NetworkItem* item = ladder()->networkItem(step, network);
                for (const auto& element : item->layout().elements)
                    if (element.address == address) {
                        *owner = item;
                        return &element;
                    }
            }
        return nullptr;
    }

    QPoint viewPoint(const QString& address) {
        ui::NetworkItem* item = nullptr;
        const ladder::ElementLayout* element = find(address, &item);
        EXPECT_NE(element, nullptr) << address.toStdString();
        if (!element)
            return {};
        const QPointF scene = item->mapToScene(item->elementRect(*element).center());
        ladder()->view()->centerOn(scene);
        return ladder()->view()->mapFromScene(scene);
    }

    void click(const QString& address) {
        QTest::mouseClick(ladder()->view()->viewport(), Qt::LeftButton, {}, viewPoint(address));
    }

    // Right-clicks the element and chooses the context menu's entry that starts with `entry`.
    void chooseFromMenu(const QString& address, const QString& entry) {
        const QPoint at = viewPoint(address);
        bool chosen = false;
        QTimer::singleShot(0, [&] {
            auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
            ASSERT_NE(menu, nullptr);
            for (QAction* item : menu->actions())
                if (item->text().remove(QLatin1Char('&')).startsWith(entry)) {
                    chosen = true;
                    menu->close();
                    item->trigger();
                    return;
                }
            menu->close();
        });
        QWidget* viewport = ladder()->view()->viewport();
        QContextMenuEvent event(QContextMenuEvent::Mouse, at, viewport->mapToGlobal(at));
        QApplication::sendEvent(viewport, &event);
        EXPECT_TRUE(chosen) << entry.toStdString();
    }

    void singleScan() { action("simulationSingleScanAction")->trigger(); }

    // The scene's colouring agrees with the engine: every element the last
    // scan left conducting (its last instruction on) is drawn in one colour,
    // every other element in another.
    void expectColouringFollowsEngine() {
        const sim::UnitEngine* unit = simulation().unit(0);
        std::map<std::pair<std::uint32_t, std::uint16_t>, bool> conducts;
        for (std::size_t i = 0; i < unit->image().code.size(); ++i) {
            const auto& in = unit->image().code[i];
            if (in.op == compiler::Op::Rung)
                continue;
            conducts[{in.statement, in.element}] = unit->conduction()[i] == sim::Conduction::On;
        }
        std::set<QRgb> on;
        std::set<QRgb> off;
        int elements = 0;
        for (int step = 0; step < ladder()->stepCount(); ++step)
            for (int network = 0; network < ladder()->networkCount(step); ++network)
                for (const auto& e : ladder()->networkItem(step, network)->layout().elements) {
                    const auto found = conducts.find({e.statement, e.element});
                    const bool powered = found != conducts.end() && found->second;
                    (powered ? on : off)
                        .insert(ladder()->elementColor(e.statement, e.element).rgb());
                    ++elements;
                }
        EXPECT_GT(elements, 10);
        EXPECT_LE(on.size(), 1u);
        EXPECT_EQ(off.size(), 1u);
        for (QRgb colour : on)
            EXPECT_EQ(off.count(colour), 0u);
    }

    QColor colourOf(const QString& address) {
        ui::NetworkItem* item = nullptr;
        const ladder::ElementLayout* element = find(address, &item);
        return element ? ladder()->elementColor(element->statement, element->element) : QColor();
    }
};

TEST_F(SimulationTest, ClickingInputsOnTheLadderDrivesTheMutingExample) {
    begin();
    const QColor unpowered = colourOf(QStringLiteral("I0.12"));
    for (const char* input : {"I0.12", "I0.13", "I0.2"})
        click(QString::fromLatin1(input));
    EXPECT_EQ(simulation().value(addressOf("I0.12")), 1);
    EXPECT_EQ(simulation().value(addressOf("I0.13")), 1);
    EXPECT_EQ(simulation().value(addressOf("I0.2")), 1);
    singleScan();
    expectColouringFollowsEngine();
    EXPECT_NE(colourOf(QStringLiteral("I0.12")), unpowered);
    EXPECT_EQ(simulation().value(addressOf("Q0.2")), 0); // no reset yet

    // Reset: the push button pressed for a scan and let go.
    click(QStringLiteral("I0.14"));
    singleScan();
    click(QStringLiteral("I0.14"));
    singleScan();
    EXPECT_EQ(simulation().value(addressOf("Q0.2")), 1);
    EXPECT_EQ(simulation().value(addressOf("Q0.3")), 1);
    expectColouringFollowsEngine();
    EXPECT_NE(colourOf(QStringLiteral("Q0.3")), unpowered);

    // The emergency stop drops the outputs.
    click(QStringLiteral("I0.12"));
    singleScan();
    EXPECT_EQ(simulation().value(addressOf("Q0.2")), 0);
    expectColouringFollowsEngine();
    EXPECT_EQ(colourOf(QStringLiteral("I0.12")), unpowered);
}

TEST_F(SimulationTest, StatusColumnShowsTheEngineValues) {
    begin();
    click(QStringLiteral("I0.12"));
    click(QStringLiteral("I0.13"));
    singleScan();
    ASSERT_TRUE(window.showPage(PageRef{PageRef::Kind::Variables, document(), 0, 0}));
    ui::VariablesPage* page = window.variablesPage();
    int checked = 0;
    for (int tab = 0; tab < page->tabs()->count(); ++tab) {
        page->tabs()->setCurrentIndex(tab);
        ui::VariableTableModel* model = page->model();
        for (int row = 0; row < model->rowCount(); ++row) {
            const auto* variable = model->variableAt(row);
            const QString status =
                model->index(row, ui::VariableTableModel::StatusColumn).data().toString();
            EXPECT_EQ(status, QString::number(simulation().value(variable->address)))
                << lang::toString(variable->address);
            ++checked;
        }
    }
    EXPECT_GT(checked, 50);

    session()->stop();
    action("simulateAction")->trigger(); // back to editing: no values
    EXPECT_FALSE(session()->isActive());
    const QString after =
        page->model()->index(0, ui::VariableTableModel::StatusColumn).data().toString();
    EXPECT_TRUE(after.isEmpty() || after == QStringLiteral("used")) << after.toStdString();
}

TEST_F(SimulationTest, ForcesAreMarkedEverywhereAndReleasedFromTheList) {
    begin();
    chooseFromMenu(QStringLiteral("M0.0"), QStringLiteral("Force M0.0 to 1"));
    singleScan();
    EXPECT_EQ(simulation().value(addressOf("M0.0")), 1);
    EXPECT_TRUE(session()->isForced(addressOf("M0.0")));
    EXPECT_EQ(mode()->liveState().forced.count(QStringLiteral("M0.0")), 1u);

    QTableWidget* forces = mode()->forcesView()->table();
    ASSERT_EQ(forces->rowCount(), 1);
    EXPECT_EQ(forces->item(0, 0)->text(), QStringLiteral("M0.0"));
    EXPECT_EQ(forces->item(0, 2)->text(), QStringLiteral("1"));

    // Clicking a forced memory flips its force; clicking an output that is not forced does nothing.
    click(QStringLiteral("M0.0"));
    EXPECT_EQ(forces->item(0, 2)->text(), QStringLiteral("0"));
    click(QStringLiteral("Q0.2"));
    EXPECT_FALSE(session()->isForced(addressOf("Q0.2")));

    ASSERT_TRUE(window.showPage(PageRef{PageRef::Kind::Variables, document(), 0, 0}));
    ASSERT_TRUE(window.variablesPage()->showVariable(addressOf("M0.0")));
    ui::VariableTableModel* model = window.variablesPage()->model();
    bool marked = false;
    for (int row = 0; row < model->rowCount(); ++row)
        if (model->variableAt(row)->address == addressOf("M0.0"))
            marked = model->index(row, ui::VariableTableModel::StatusColumn).data().toString() ==
                     QStringLiteral("0 F");
    EXPECT_TRUE(marked);

    forces->selectRow(0);
    mode()->forcesView()->findChild<QPushButton*>(QStringLiteral("releaseForceButton"))->click();
    EXPECT_EQ(forces->rowCount(), 0);
    EXPECT_FALSE(session()->isForced(addressOf("M0.0")));
    // The project itself never changes.
    EXPECT_FALSE(document()->isModified());
}

TEST_F(SimulationTest, WatchSetsAndForcesByName) {
    begin();
    ui::WatchView* watch = mode()->watchView();
    EXPECT_TRUE(watch->add(QStringLiteral("Q0.2")).isEmpty());
    EXPECT_TRUE(watch->add(QStringLiteral("I0.12")).isEmpty());
    EXPECT_FALSE(watch->add(QStringLiteral("NoSuchName")).isEmpty());
    ASSERT_EQ(watch->table()->rowCount(), 2);
    watch->table()->item(1, ui::WatchView::ValueColumn)->setText(QStringLiteral("1"));
    EXPECT_EQ(simulation().value(addressOf("I0.12")), 1);
    EXPECT_FALSE(session()->isForced(addressOf("I0.12"))); // an input is set, not forced
    watch->table()->item(0, ui::WatchView::ValueColumn)->setText(QStringLiteral("1"));
    EXPECT_TRUE(session()->isForced(addressOf("Q0.2")));
    singleScan();
    EXPECT_EQ(watch->table()->item(0, ui::WatchView::ValueColumn)->text(), QStringLiteral("1 F"));
}

TEST_F(SimulationTest, WaveformRecordsTheRunAndExportsVcd) {
    begin();
    ASSERT_TRUE(mode()->waveformPanel()->add(QStringLiteral("Q0.14")).isEmpty());
    click(QStringLiteral("I0.12"));
    for (int i = 0; i < 5; ++i)
        singleScan();
    const sim::WaveformRecorder& recorder = session()->recorder();
    EXPECT_EQ(recorder.endMs(), 50);
    const auto& traces = recorder.traces();
    const auto input = std::find_if(traces.begin(), traces.end(),
                                    [](const auto& t) { return t.address == addressOf("I0.12"); });
    ASSERT_NE(input, traces.end());
    ASSERT_EQ(input->changes.size(), 2u); // 0 at power on, 1 from the click
    EXPECT_EQ(input->changes.back().value, 1);
    const QString out = directory.filePath(QStringLiteral("run.vcd"));
    EXPECT_TRUE(mode()->waveformPanel()->exportVcd(out).isEmpty());
    const QByteArray vcd = readFile(out);
    EXPECT_TRUE(vcd.contains("$var wire 1 \" Q14 $end")) << vcd.toStdString();
    EXPECT_TRUE(vcd.contains("I12 $end"));

    // Remove All empties the plot; the next scans record nothing more.
    mode()
        ->waveformPanel()
        ->findChild<QToolButton*>(QStringLiteral("removeAllTracesButton"))
        ->click();
    EXPECT_TRUE(recorder.traces().empty());
    singleScan();
    EXPECT_TRUE(recorder.traces().empty());
    EXPECT_TRUE(mode()->waveformPanel()->add(QStringLiteral("Q0.14")).isEmpty());
    singleScan();
    ASSERT_EQ(recorder.traces().size(), 1u);
}

TEST_F(SimulationTest, ScenarioResultsListFailuresThatOpenTheirLine) {
    const QString path = writeFile(QStringLiteral("start.scn"),
                                   "set I0.12 1\nset I0.13 1\nset I0.2 1\nrun 50ms\n"
                                   "expect Q0.14 1\nset I0.14 1\nrun 20ms\nset I0.14 0\n"
                                   "expect Q0.2 1\nexpect Q0.3 0   ; wrong on purpose\n");
    const auto result = mode()->runScenario(path);
    EXPECT_EQ(result.passed, 2);
    EXPECT_EQ(result.failed, 1);
    ASSERT_EQ(result.failures.size(), 1u);
    EXPECT_EQ(result.failures[0].line, 10);
    // The window shows the state the scenario ended in.
    EXPECT_EQ(simulation().value(addressOf("Q0.2")), 1);
    EXPECT_TRUE(ladder()->isLive());
    EXPECT_EQ(session()->state(), ui::SimulationSession::State::Stopped);
    EXPECT_GE(session()->recorder().endMs(), 70);

    QTreeWidget* tree = mode()->scenarioResults()->tree();
    ASSERT_EQ(tree->topLevelItemCount(), 1);
    EXPECT_EQ(tree->topLevelItem(0)->text(0), QStringLiteral("start.scn: 2 passed, 1 failed"));
    QTreeWidgetItem* failure = tree->topLevelItem(0)->child(0);
    EXPECT_TRUE(failure->text(0).startsWith(QStringLiteral("start.scn:10: expect Q0.3 0")));
    emit tree->itemActivated(failure, 0);
    EXPECT_TRUE(mode()->scenarioViewer()->isVisible());
    EXPECT_EQ(mode()->scenarioViewer()->currentLine(), 10);
    mode()->scenarioViewer()->close();
}

TEST_F(SimulationTest, EditingTheProjectEndsTheSimulation) {
    begin();
    action("simulationStartAction")->trigger();
    EXPECT_EQ(session()->state(), ui::SimulationSession::State::Running);
    QTest::qWait(60);
    EXPECT_GT(simulation().timeMs(), 0);
    document()->edit(QStringLiteral("rename"), [](project::Project& p) {
        project::setVariableName(p, addressOf("M0.1"), "Spare");
    });
    EXPECT_FALSE(session()->isActive());
    EXPECT_FALSE(ladder()->isLive());
}

TEST_F(SimulationTest, LiveStateKeptUpToDateEqualsOneBuiltAfresh) {
    begin();
    ui::LiveLadderBuilder kept;
    ui::LadderLiveState live;
    kept.update(live, simulation(), 0);
    auto same = [&] {
        ui::LiveLadderBuilder fresh;
        ui::LadderLiveState expected;
        fresh.update(expected, simulation(), 0);
        kept.update(live, simulation(), 0);
        ASSERT_EQ(live.power.statements.size(), expected.power.statements.size());
        for (const auto& [statement, power] : expected.power.statements) {
            EXPECT_EQ(live.power.statements[statement].conducting, power.conducting) << statement;
            EXPECT_EQ(live.power.statements[statement].energised, power.energised) << statement;
        }
        EXPECT_EQ(live.annotations, expected.annotations);
        EXPECT_EQ(live.forced, expected.forced);
        EXPECT_EQ(live.activeSteps, expected.activeSteps);
    };
    for (const char* input : {"I0.12", "I0.13", "I0.2", "I0.14"}) {
        session()->toggle(addressOf(input));
        singleScan();
        same();
    }
    session()->force(addressOf("M0.0"), 1);
    session()->toggle(addressOf("I0.0"));
    session()->toggle(addressOf("I0.1"));
    for (int i = 0; i < 3; ++i) {
        singleScan();
        same();
    }
    EXPECT_EQ(live.activeSteps.at(1), simulation().unit(0)->activeStep(1));
    EXPECT_EQ(live.forced.count(QStringLiteral("M0.0")), 1u);
}

TEST_F(SimulationTest, TheClockRunsAtTheChosenSpeedAndStops) {
    begin();
    auto* speed = mode()->controls()->speed();
    speed->setCurrentIndex(speed->findData(ui::SimulationSession::kAsFastAsPossible));
    action("simulationStartAction")->trigger();
    QTest::qWait(100);
    action("simulationStopAction")->trigger();
    EXPECT_EQ(session()->state(), ui::SimulationSession::State::Stopped);
    // As fast as possible: far more than the 10 scans of 100 ms in real time.
    const std::int64_t reached = simulation().timeMs();
    EXPECT_GT(reached, 1000);
    QTest::qWait(30);
    EXPECT_EQ(simulation().timeMs(), reached);
    EXPECT_TRUE(mode()->controls()->clock()->text().contains(
        QString::number(static_cast<double>(reached) / 1000.0, 'f', 3)));
    action("simulationResetAction")->trigger();
    EXPECT_EQ(simulation().timeMs(), 0);
}

TEST_F(SimulationTest, BusStatusListsTheUnitsAndTheStatusBarTheCode) {
    ASSERT_TRUE(
        window.loadFile(QStringLiteral(RUNGSMITH_SOURCE_DIR "/resources/examples/press-line.sps"))
            .isEmpty());
    ASSERT_TRUE(window.showPage(PageRef{PageRef::Kind::Ladder, document(), 0, 0}));
    begin();
    QTableWidget* bus = mode()->busStatusView()->table();
    ASSERT_EQ(bus->rowCount(), 2);
    EXPECT_EQ(bus->item(0, ui::BusStatusView::StationColumn)->text(), QStringLiteral("0"));
    EXPECT_EQ(bus->item(1, ui::BusStatusView::StationColumn)->text(), QStringLiteral("1"));
    EXPECT_EQ(bus->item(1, ui::BusStatusView::CodeColumn)->text(), QStringLiteral("E0=No Error"));
    // Each unit's program signature, as the command line prints it (issue 18).
    QProcess cli;
    cli.start(QStringLiteral(RUNGSMITH_CLI),
              {QStringLiteral("signature"),
               QStringLiteral(RUNGSMITH_SOURCE_DIR "/resources/examples/press-line.sps")});
    ASSERT_TRUE(cli.waitForFinished(30000));
    const QString printed = QString::fromUtf8(cli.readAllStandardOutput());
    for (int row = 0; row < 2; ++row) {
        const QString signature = bus->item(row, ui::BusStatusView::SignatureColumn)->text();
        EXPECT_EQ(signature.size(), 8);
        EXPECT_TRUE(printed.contains(signature)) << printed.toStdString();
    }
    EXPECT_EQ(mode()->unitCode()->text(), QStringLiteral("Pluto 0: E0=No Error"));
    session()->force(addressOf("SR1.11"), 26);
    EXPECT_EQ(bus->item(1, ui::BusStatusView::CodeColumn)->text(), QStringLiteral("Er26"));
}

TEST_F(SimulationTest, CommandLineScreenshotShowsTheStateAScenarioEndsIn) {
    const QString scenario =
        writeFile(QStringLiteral("reset.scn"),
                  "set I0.12 1\nset I0.13 1\nset I0.2 1\nrun 50ms\n"
                  "set I0.14 1\nrun 20ms\nset I0.14 0\nrun 20ms\nexpect I0.14 0\n");
    const QString out = directory.filePath(QStringLiteral("live.png"));
    QProcess gui;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    environment.insert(QStringLiteral("XDG_CONFIG_HOME"), directory.path());
    gui.setProcessEnvironment(environment);
    gui.start(QStringLiteral(RUNGSMITH_GUI),
              {QStringLiteral("--simulate"), scenario, QStringLiteral("--screenshot"), out,
               QStringLiteral("--page"), QStringLiteral("ladder:0")});
    ASSERT_TRUE(gui.waitForFinished(60000));
    EXPECT_EQ(gui.exitCode(), 0) << gui.readAllStandardError().toStdString();
    EXPECT_FALSE(QImage(out).isNull());

    gui.start(QStringLiteral(RUNGSMITH_GUI),
              {QStringLiteral("--simulate"), directory.filePath(QStringLiteral("missing.scn")),
               QStringLiteral("--screenshot"), out});
    ASSERT_TRUE(gui.waitForFinished(60000));
    EXPECT_EQ(gui.exitCode(), 2);
    EXPECT_TRUE(gui.readAllStandardError().contains("missing.scn"));
}

TEST_F(SimulationTest, AnotherProjectsPagesShowNoValues) {
    ui::ProjectDocument* muting = document();
    ASSERT_TRUE(
        window.loadFile(QStringLiteral(RUNGSMITH_SOURCE_DIR "/resources/examples/press-line.sps"))
            .isEmpty());
    ASSERT_TRUE(window.showPage(PageRef{PageRef::Kind::Ladder, document(), 0, 0}));
    begin();
    session()->set(addressOf("I0.0"), 1);
    ASSERT_TRUE(window.showPage(PageRef{PageRef::Kind::Variables, muting, 0, 0}));
    ui::VariableTableModel* model = window.variablesPage()->model();
    ASSERT_GT(model->rowCount(), 0);
    const QString other = model->index(0, ui::VariableTableModel::StatusColumn).data().toString();
    EXPECT_TRUE(other.isEmpty() || other == QStringLiteral("used")) << other.toStdString();
    ASSERT_TRUE(window.showPage(PageRef{PageRef::Kind::Ladder, muting, 0, 0}));
    EXPECT_FALSE(ladder()->isLive());
    ASSERT_TRUE(window.showPage(PageRef{PageRef::Kind::Variables, session()->document(), 0, 0}));
    EXPECT_EQ(model->index(0, ui::VariableTableModel::StatusColumn).data().toString(),
              QStringLiteral("1"));
}

// Issue 17, finding 6: docks belong to a mode and a project, and go with them.
TEST_F(SimulationTest, TheSimulationDocksGoWithTheSimulationAndComeBackAsLeft) {
    window.resize(1024, 600);
    auto* forces = window.findChild<QDockWidget*>(QStringLiteral("forcesDock"));
    auto* watch = window.findChild<QDockWidget*>(QStringLiteral("watchDock"));
    auto* waveform = window.findChild<QDockWidget*>(QStringLiteral("waveformDock"));
    ASSERT_TRUE(forces && watch && waveform);
    begin();
    QApplication::processEvents();
    EXPECT_TRUE(forces->isVisible());
    EXPECT_TRUE(waveform->isVisible());
    // The page keeps most of the height.
    EXPECT_LE(waveform->height(), window.height() * 3 / 10 + 1);
    watch->close();

    action("simulateAction")->trigger();
    ASSERT_FALSE(session()->isActive());
    EXPECT_FALSE(forces->isVisible());
    EXPECT_FALSE(waveform->isVisible());

    begin();
    EXPECT_TRUE(forces->isVisible());
    EXPECT_TRUE(waveform->isVisible());
    EXPECT_FALSE(watch->isVisible());
}

TEST_F(SimulationTest, AnotherProjectStartsWithoutTheLastOnesTracesWatchesAndResults) {
    begin();
    ASSERT_TRUE(mode()->waveformPanel()->add(QStringLiteral("Q0.14")).isEmpty());
    ASSERT_TRUE(mode()->watchView()->add(QStringLiteral("Q0.14")).isEmpty());
    // The same project again keeps what was chosen for it.
    action("simulateAction")->trigger();
    begin();
    EXPECT_FALSE(session()->recorder().traces().empty());
    EXPECT_EQ(mode()->watchView()->variables().size(), 1u);
    action("simulateAction")->trigger();

    ASSERT_TRUE(
        window.loadFile(QStringLiteral(RUNGSMITH_SOURCE_DIR "/resources/examples/press-line.sps"))
            .isEmpty());
    ASSERT_TRUE(window.showPage(PageRef{PageRef::Kind::Ladder, document(), 0, 0}));
    begin();
    EXPECT_TRUE(session()->recorder().traces().empty());
    EXPECT_TRUE(mode()->watchView()->variables().empty());
}

TEST_F(SimulationTest, ClosingTheSimulatedProjectTakesItsScenarioResultsAway) {
    const QString path = writeFile(QStringLiteral("start.scn"), "set I0.12 1\nrun 50ms\n");
    const auto result = mode()->runScenario(path);
    ASSERT_TRUE(result.error.isEmpty()) << result.error.toStdString();
    auto* scenarios = window.findChild<QDockWidget*>(QStringLiteral("scenariosDock"));
    ASSERT_TRUE(scenarios);
    EXPECT_EQ(mode()->scenarioResults()->tree()->topLevelItemCount(), 1);
    ASSERT_TRUE(window.closeDocument(document()));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
    EXPECT_EQ(mode()->scenarioResults()->tree()->topLevelItemCount(), 0);
    EXPECT_FALSE(scenarios->isVisible());
}

// Issue 17, finding 7: no column heading of the simulation docks is cut, in any language.
TEST_F(SimulationTest, TheForcesAndWatchHeadingsAreNotCut) {
    begin();
    session()->force(addressOf("Q0.2"), 1);
    ASSERT_TRUE(mode()->watchView()->add(QStringLiteral("Q0.14")).isEmpty());
    for (const char* name : {"forcesTable", "watchTable"}) {
        auto* table = window.findChild<QTableWidget*>(QLatin1String(name));
        ASSERT_NE(table, nullptr) << name;
        QHeaderView* header = table->horizontalHeader();
        for (int column = 0; column + 1 < header->count(); ++column)
            EXPECT_GE(header->sectionSize(column), header->sectionSizeHint(column))
                << name << " column " << column;
    }
}

// Issue 17, live view: the Variables page toggles and forces while simulating,
// and outside simulation says "used" in words, not with a dot like a value.
TEST_F(SimulationTest, TheVariablesPageTogglesAndForcesWhileSimulating) {
    ASSERT_TRUE(window.showPage(PageRef{PageRef::Kind::Variables, document(), 0, 0}));
    ui::VariablesPage* page = window.variablesPage();
    QTableView* table = page->table();
    auto rowOf = [&](const char* word) {
        for (int row = 0; row < table->model()->rowCount(); ++row)
            if (table->model()->index(row, 0).data(ui::VariableTableModel::kAddressRole) ==
                QLatin1String(word))
                return row;
        return -1;
    };
    const int row = rowOf("I0.12");
    ASSERT_GE(row, 0);
    const QModelIndex status = table->model()->index(row, ui::VariableTableModel::StatusColumn);
    EXPECT_EQ(status.data().toString(), QStringLiteral("used"));
    EXPECT_TRUE(status.data(Qt::DecorationRole).isNull());

    ASSERT_TRUE(window.showPage(PageRef{PageRef::Kind::Ladder, document(), 0, 0}));
    begin();
    ASSERT_TRUE(window.showPage(PageRef{PageRef::Kind::Variables, document(), 0, 0}));
    const QPoint cell = table->visualRect(status).center();
    QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, cell);
    QTest::mouseDClick(table->viewport(), Qt::LeftButton, {}, cell);
    EXPECT_EQ(simulation().value(addressOf("I0.12")), 1);
    EXPECT_FALSE(table->indexWidget(status)); // no editor: the project is not edited
    table->setFocus();
    table->setCurrentIndex(status);
    QTest::keyClick(table, Qt::Key_Space);
    EXPECT_EQ(simulation().value(addressOf("I0.12")), 0);
    EXPECT_FALSE(document()->isModified());

    // The context menu forces, releases and watches.
    QTimer::singleShot(0, [&] {
        auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
        ASSERT_NE(menu, nullptr);
        EXPECT_EQ(menu->objectName(), QStringLiteral("forceMenu"));
        for (QAction* action : menu->actions())
            if (action->text().contains(QStringLiteral("&1")))
                action->trigger();
        menu->close();
    });
    emit table->customContextMenuRequested(cell);
    EXPECT_TRUE(session()->isForced(addressOf("I0.12")));
}

// Issue 17, live view: "ladder lines off" is the colour of what carries no
// power while simulating, "ladder lines" while editing.
TEST_F(SimulationTest, LinesOffAreTheColourOfUnpoweredLinesWhileSimulating) {
    ui::LadderColours chosen;
    chosen.lines = QColor(0xff, 0xee, 0x00);
    chosen.linesOff = QColor(0x00, 0xee, 0xff);
    chosen.linesOn = QColor(0xee, 0x00, 0xff);
    ladder()->setColours(chosen);
    EXPECT_EQ(ladder()->drawing().style.ink, chosen.lines);
    begin();
    EXPECT_EQ(ladder()->drawing().style.ink, chosen.linesOff);
    EXPECT_EQ(ladder()->drawing().style.powered, chosen.linesOn);
    action("simulateAction")->trigger();
    EXPECT_EQ(ladder()->drawing().style.ink, chosen.lines);
}

// Issue 19: the Watch dock sets one channel of a safe AS-i slave, and the
// slave's input follows its channel monitoring.
TEST_F(SimulationTest, WatchSetsTheChannelsOfASafeAsiSlave) {
    ASSERT_TRUE(
        window.loadFile(QStringLiteral(RUNGSMITH_SOURCE_DIR "/tests/scenarios/asi_channels.sps"))
            .isEmpty());
    ASSERT_TRUE(window.showPage(PageRef{PageRef::Kind::Ladder, document(), 0, 0}));
    begin();
    ui::WatchView* watch = mode()->watchView();
    EXPECT_TRUE(session()->operandWords().contains(QStringLiteral("Door.ch2")));
    ASSERT_TRUE(watch->add(QStringLiteral("Door.ch1")).isEmpty());
    ASSERT_TRUE(watch->add(QStringLiteral("asi0.2.CH2")).isEmpty());
    ASSERT_TRUE(watch->add(QStringLiteral("Door")).isEmpty());
    EXPECT_FALSE(watch->add(QStringLiteral("DoorOn.ch1")).isEmpty()); // a memory has no channels
    ASSERT_EQ(watch->table()->rowCount(), 3);
    EXPECT_EQ(watch->table()->item(0, ui::WatchView::VariableColumn)->text(),
              QStringLiteral("ASi0.2.ch1"));
    EXPECT_EQ(watch->table()->item(1, ui::WatchView::NameColumn)->text(),
              QStringLiteral("Door.ch2"));
    auto value = [&](int row) {
        return watch->table()->item(row, ui::WatchView::ValueColumn)->text();
    };
    watch->table()->item(0, ui::WatchView::ValueColumn)->setText(QStringLiteral("1"));
    singleScan();
    EXPECT_EQ(value(0), QStringLiteral("1"));
    EXPECT_EQ(value(2), QStringLiteral("0")); // one channel is not enough
    watch->table()->item(1, ui::WatchView::ValueColumn)->setText(QStringLiteral("1"));
    singleScan();
    EXPECT_EQ(value(2), QStringLiteral("1"));
    // Channel monitoring: one channel opening drops the input until both have opened.
    watch->table()->item(0, ui::WatchView::ValueColumn)->setText(QStringLiteral("0"));
    singleScan();
    watch->table()->item(0, ui::WatchView::ValueColumn)->setText(QStringLiteral("1"));
    singleScan();
    EXPECT_EQ(value(2), QStringLiteral("0"));
    EXPECT_EQ(simulation().value(addressOf("SR0.16")), 2);
    watch->table()->item(0, ui::WatchView::ValueColumn)->setText(QStringLiteral("2"));
    EXPECT_EQ(value(0), QStringLiteral("1")); // refused: a channel is 0 or 1
    EXPECT_FALSE(document()->isModified());
}

} // namespace
