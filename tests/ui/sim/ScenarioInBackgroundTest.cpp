// SPDX-License-Identifier: GPL-3.0-or-later
#include "WindowTest.h"

#include "sim/ScenarioResultsView.h"
#include "sim/SimulationControls.h"
#include "sim/SimulationMode.h"

#include <QAction>
#include <QElapsedTimer>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <QTreeWidget>

#include "QtPrinting.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

// Virtual time that takes the simulator minutes of wall time.
const QByteArray kEndless = "set I0.12 1\nrun 20000min\nexpect Q0.14 1\n";

class ScenarioInBackgroundTest : public WindowTest {
protected:
    void SetUp() override {
        WindowTest::SetUp();
        window.showExample();
        showWindow();
    }

    ui::SimulationMode* mode() { return window.simulation(); }
    ui::SimulationSession* session() { return mode()->session(); }

    // The results the session gives, in order.
    void collectResults() {
        QObject::connect(session(), &ui::SimulationSession::scenarioFinished, session(),
                         [this](const ui::SimulationSession::ScenarioResult& result) {
                             results.push_back(result);
                         });
    }
    std::vector<ui::SimulationSession::ScenarioResult> results;
};

TEST_F(ScenarioInBackgroundTest, ALongScenarioLeavesTheWindowResponsiveAndCancels) {
    const QString path = writeFile(QStringLiteral("endless.scn"), kEndless);
    QSignalSpy progress(session(), &ui::SimulationSession::scenarioProgress);
    collectResults();
    mode()->startScenario(path);
    ASSERT_TRUE(session()->isRunningScenario());
    EXPECT_TRUE(mode()->scenarioProgress()->isVisible());
    EXPECT_TRUE(mode()->cancelScenarioButton()->isVisible());
    EXPECT_FALSE(mode()->controls()->runScenarioAction()->isEnabled());

    // The window's event loop goes on while the scenario runs.
    int fired = 0;
    QTimer timer;
    QObject::connect(&timer, &QTimer::timeout, [&] { ++fired; });
    timer.start(10);
    QTest::qWait(500);
    EXPECT_GE(fired, 10);
    EXPECT_TRUE(results.empty());
    ASSERT_GE(progress.size(), 2);
    const qint64 reached = progress.last().at(0).toLongLong();
    EXPECT_GT(reached, 0);
    EXPECT_EQ(progress.last().at(1).toLongLong(), 20000LL * 60 * 1000);
    EXPECT_GT(mode()->scenarioProgress()->value(), -1);

    QElapsedTimer cancelling;
    cancelling.start();
    QTest::mouseClick(mode()->cancelScenarioButton(), Qt::LeftButton);
    EXPECT_TRUE(QTest::qWaitFor([&] { return !results.empty(); }, 5000));
    EXPECT_LT(cancelling.elapsed(), 2000);
    ASSERT_EQ(results.size(), 1u);
    const auto& result = results.front();
    EXPECT_TRUE(result.cancelled);
    EXPECT_EQ(result.passed + result.failed, 0);
    EXPECT_GE(result.endMs, reached);

    // A clean state: stopped where it got, and ready for anything again.
    EXPECT_FALSE(session()->isRunningScenario());
    EXPECT_EQ(session()->state(), ui::SimulationSession::State::Stopped);
    EXPECT_EQ(session()->simulation()->timeMs(), result.endMs);
    EXPECT_FALSE(mode()->scenarioProgress()->isVisible());
    EXPECT_FALSE(mode()->cancelScenarioButton()->isVisible());
    EXPECT_TRUE(mode()->controls()->runScenarioAction()->isEnabled());
    QTreeWidget* tree = mode()->scenarioResults()->tree();
    ASSERT_EQ(tree->topLevelItemCount(), 1);
    EXPECT_TRUE(tree->topLevelItem(0)->text(0).contains(QStringLiteral("cancelled")))
        << tree->topLevelItem(0)->text(0).toStdString();

    session()->singleScan();
    EXPECT_EQ(session()->simulation()->timeMs(), result.endMs + 10);
}

TEST_F(ScenarioInBackgroundTest, EndingTheSimulationCancelsARunningScenario) {
    const QString path = writeFile(QStringLiteral("endless.scn"), kEndless);
    collectResults();
    mode()->startScenario(path);
    QTest::qWait(50);
    mode()->end();
    ASSERT_EQ(results.size(), 1u);
    EXPECT_TRUE(results.front().cancelled);
    EXPECT_FALSE(session()->isActive());
    EXPECT_FALSE(session()->isRunningScenario());
}

TEST_F(ScenarioInBackgroundTest, AShortScenarioGivesTheSameResultsAsBefore) {
    // The muting example: the same file and figures as the simulation tests'.
    const QString path = writeFile(QStringLiteral("start.scn"),
                                   "set I0.12 1\nset I0.13 1\nset I0.2 1\nrun 50ms\n"
                                   "expect Q0.14 1\nset I0.14 1\nrun 20ms\nset I0.14 0\n"
                                   "expect Q0.2 1\nexpect Q0.3 0   ; wrong on purpose\n");
    const auto result = mode()->runScenario(path);
    EXPECT_FALSE(result.cancelled);
    EXPECT_EQ(result.passed, 2);
    EXPECT_EQ(result.failed, 1);
    EXPECT_EQ(result.endMs, 70);
    EXPECT_EQ(session()->simulation()->timeMs(), 70);
    EXPECT_EQ(session()->simulation()->value(lang::readAddressWord("Q0.2").address), 1);
    EXPECT_GE(session()->recorder().endMs(), 70);
}

} // namespace
