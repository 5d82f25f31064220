// SPDX-License-Identifier: GPL-3.0-or-later
#include "DiagnosticsText.h"
#include "WindowTest.h"

#include "document/ProjectDocument.h"
#include "ladder/LadderPage.h"
#include "ladder/LadderView.h"
#include "ladder/NetworkItem.h"
#include "shell/Theme.h"
#include "sim/SimulationMode.h"

#include <QAction>
#include <QApplication>
#include <QImage>
#include <QLabel>
#include <QScrollBar>
#include <QTest>

#include <gtest/gtest.h>

using namespace rs;
using rs::test::addressOf;
using rs::ui::PageRef;

namespace {

// The live ladder of the muting example, whose first network is
// Q0.2 = I0.12 * (I0.13 + M0.0) * (P(I0.14) * I0.2 + Q0.2), then Q0.3 = Q0.2
// and Q0.14 = /Q0.2: every element shows its own state, and a selected
// output says why it is on or off.
class LiveViewTest : public WindowTest {
protected:
    void SetUp() override {
        WindowTest::SetUp();
        window.showExample();
        showWindow();
        ASSERT_TRUE(window.showPage(PageRef{PageRef::Kind::Ladder, document(), 0, 0}));
        window.simulation()->session()->setUpdateInterval(1);
        action("simulateAction")->trigger();
        ASSERT_TRUE(ladder()->isLive());
    }

    ui::SimulationSession* session() { return window.simulation()->session(); }
    ui::LadderPage* ladder() { return window.ladderPage(); }
    void singleScan() { action("simulationSingleScanAction")->trigger(); }
    void set(const char* address, std::int64_t value) { session()->set(addressOf(address), value); }

    // The first element with this address on the page: a condition's
    // element, or an output's when `output`.
    const ladder::ElementLayout* find(const QString& address, bool output,
                                      ui::NetworkItem** owner = nullptr) {
        for (int step = 0; step < ladder()->stepCount(); ++step)
            for (int network = 0; network < ladder()->networkCount(step); ++network) {
                ui::NetworkItem* item = ladder()->networkItem(step, network);
                for (const auto& e : item->layout().elements)
                    if (e.address == address && (e.output >= 0) == output) {
                        if (owner)
                            *owner = item;
                        return &e;
                    }
            }
        ADD_FAILURE() << address.toStdString();
        return nullptr;
    }

    std::pair<std::uint32_t, std::uint16_t> key(const char* address, bool output = false) {
        const ladder::ElementLayout* e = find(QString::fromLatin1(address), output);
        return e ? std::make_pair(e->statement, e->element) : std::make_pair(0u, std::uint16_t{0});
    }

    QPoint viewPoint(const char* address, bool output, QPointF offset = {}) {
        ui::NetworkItem* item = nullptr;
        const ladder::ElementLayout* e = find(QString::fromLatin1(address), output, &item);
        if (!e)
            return {};
        const QPointF scene = item->mapToScene(e->symbolRect.center() + offset +
                                               QPointF(ui::NetworkItem::kGutter, 0));
        ladder()->view()->centerOn(scene);
        return ladder()->view()->mapFromScene(scene);
    }

    // The colour the page shows inside the element's symbol, a little below
    // its middle (clear of a letter).
    QColor fillOf(const char* address, bool output = false) {
        const QPoint at = viewPoint(address, output, {0, 5});
        return ladder()->view()->viewport()->grab().toImage().pixelColor(at);
    }

    QColor closedFill() { return ladder()->drawing().style.closedFill; }

    void clickOutput(const char* address) {
        QTest::mouseClick(ladder()->view()->viewport(), Qt::LeftButton, {},
                          viewPoint(address, true));
    }

    QString status() {
        return ladder()->findChild<QLabel*>(QStringLiteral("ladderStatus"))->text();
    }
};

TEST_F(LiveViewTest, AClosedContactWithNoPowerArrivingIsDrawnClosed) {
    set("I0.2", 1); // the reset branch: P(I0.14) before it is open
    singleScan();
    EXPECT_EQ(fillOf("I0.2"), closedFill());
    EXPECT_FALSE(ladder()->liveState()->power.conducts(key("I0.2").first, key("I0.2").second))
        << "no power passes it";
    EXPECT_NE(fillOf("I0.13"), closedFill()) << "open";
    set("I0.2", 0);
    singleScan();
    EXPECT_NE(fillOf("I0.2"), closedFill());
}

TEST_F(LiveViewTest, ACoilForcedOnWithItsRungOffIsDrawnOnWithTheBadge) {
    session()->force(addressOf("Q0.3"), 1);
    singleScan();
    EXPECT_FALSE(ladder()->liveState()->power.conducts(key("Q0.3", true).first, 0));
    EXPECT_EQ(fillOf("Q0.3", true), closedFill()) << "forced on, though its rung is off";
    ui::NetworkItem* item = nullptr;
    const ladder::ElementLayout* coil = find(QStringLiteral("Q0.3"), true, &item);
    ASSERT_NE(coil, nullptr);
    // The badge stands at the symbol's top right corner; near its own corner,
    // clear of its letter.
    const QPoint badge = viewPoint(
        "Q0.3", true, {coil->symbolRect.width() / 2 + 5, -coil->symbolRect.height() / 2 - 7});
    EXPECT_EQ(ladder()->view()->viewport()->grab().toImage().pixelColor(badge),
              ladder()->drawing().problem);
    session()->release(addressOf("Q0.3"));
    singleScan();
    EXPECT_NE(fillOf("Q0.3", true), closedFill());
}

TEST_F(LiveViewTest, SelectingAnOutputThatIsOffNamesAndMarksWhatBlocksEachPath) {
    set("I0.12", 1);
    singleScan();
    clickOutput("Q0.2");
    EXPECT_EQ(ladder()->outputExplanation(),
              QStringLiteral("Q0.2 is off: I0.13 is open, M0.0 is open"));
    EXPECT_EQ(status(), ladder()->outputExplanation());
    EXPECT_EQ(ladder()->blockingElements(),
              (std::set<std::pair<std::uint32_t, std::uint16_t>>{key("I0.13"), key("M0.0")}));
    EXPECT_TRUE(ladder()->holdingElements().empty());

    // The next scan answers again, with no new click.
    set("I0.13", 1);
    singleScan();
    EXPECT_EQ(ladder()->outputExplanation(),
              QStringLiteral("Q0.2 is off: M0.0 is open, P(I0.14) is open, Q0.2 is open"))
        << "every path: the one through M0.0 too";
    EXPECT_EQ(ladder()->blockingElements(), (std::set<std::pair<std::uint32_t, std::uint16_t>>{
                                                key("M0.0"), key("I0.14"), key("Q0.2")}));

    // Reset: on, held by the path through the reset branch, then by itself.
    set("I0.2", 1);
    set("I0.14", 1);
    singleScan();
    EXPECT_EQ(ladder()->outputExplanation(),
              QStringLiteral("Q0.2 is on through I0.12, I0.13, P(I0.14), I0.2"));
    EXPECT_EQ(ladder()->holdingElements().size(), 4u);
    EXPECT_TRUE(ladder()->blockingElements().empty());
    singleScan();
    EXPECT_EQ(ladder()->outputExplanation(),
              QStringLiteral("Q0.2 is on through I0.12, I0.13, Q0.2"));
}

TEST_F(LiveViewTest, AForcedOutputSaysSoAndWhatItsRungDoes) {
    session()->force(addressOf("Q0.3"), 1);
    singleScan();
    clickOutput("Q0.3");
    EXPECT_EQ(ladder()->outputExplanation(),
              QStringLiteral("Q0.3 is forced on; its rung is off: Q0.2 is open"));
    clickOutput("Q0.14"); // Q0.14 = /Q0.2
    EXPECT_EQ(ladder()->outputExplanation(), QStringLiteral("Q0.14 is on through /Q0.2"));
    // Leaving the simulation takes the answer and its marks away.
    action("simulateAction")->trigger();
    EXPECT_FALSE(ladder()->isLive());
    EXPECT_TRUE(ladder()->outputExplanation().isEmpty());
    EXPECT_TRUE(ladder()->holdingElements().empty());
    EXPECT_TRUE(status().isEmpty());
}

// The pictures of docs/simulation.md, "Every element's own state": written
// only when RUNGSMITH_PICTURES names a folder (light and dark; the greyscale
// ones are made from them with ImageMagick's convert -colorspace Gray).
TEST_F(LiveViewTest, PicturesForTheDocumentation) {
    const QString folder = qEnvironmentVariable("RUNGSMITH_PICTURES");
    if (folder.isEmpty())
        GTEST_SKIP() << "set RUNGSMITH_PICTURES to a folder to write them";
    // I0.2 closed with no power (P(I0.14) before it is open), I0.13 and M0.0
    // open with power at their left, Q0.3 forced on with its rung off, and
    // why Q0.2 is off.
    set("I0.12", 1);
    set("I0.2", 1);
    session()->force(addressOf("Q0.3"), 1);
    singleScan();
    clickOutput("Q0.2");
    window.resize(1000, 1040);
    for (const auto& [theme, name] : {std::pair{ui::Preferences::Theme::Light, "light"},
                                      std::pair{ui::Preferences::Theme::Dark, "dark"}}) {
        ui::applyTheme(theme);
        QApplication::processEvents();
        ladder()->view()->verticalScrollBar()->setValue(0);
        ladder()->view()->horizontalScrollBar()->setValue(0);
        QApplication::processEvents();
        const QString path = folder + QStringLiteral("/sim-states-%1.png").arg(QLatin1String(name));
        EXPECT_TRUE(ladder()->grab().save(path)) << path.toStdString();
    }
    ui::applyTheme(ui::Preferences::Theme::Light);
}

// A timer and a comparison that block their rungs are named as such.
TEST_F(LiveViewTest, ATimerOrComparisonThatBlocksSaysSo) {
    action("simulateAction")->trigger(); // leave the example's simulation
    const QString path =
        writeFile(QStringLiteral("boxes.sps"),
                  "! id_pluto:00=000000000000\n! type_pluto:00=A20,is3\n! pgm_pluto:00\nS0.0_0\n"
                  "Q0.10 = I0.2 * TON(5s10)\nM0.0 = I0.0 * (R0.1 > 4)\n");
    ASSERT_TRUE(window.loadFile(path).isEmpty());
    ASSERT_TRUE(window.showPage(PageRef{PageRef::Kind::Ladder, document(), 0, 0}));
    window.simulation()->session()->setUpdateInterval(1);
    action("simulateAction")->trigger();
    ASSERT_TRUE(ladder()->isLive());
    set("I0.2", 1);
    set("I0.0", 1);
    singleScan();
    clickOutput("Q0.10");
    EXPECT_EQ(ladder()->outputExplanation(), QStringLiteral("Q0.10 is off: TON 5s10 is off"));
    clickOutput("M0.0");
    EXPECT_EQ(ladder()->outputExplanation(), QStringLiteral("M0.0 is off: R0.1 > 4 is false"));
    set("R0.1", 5); // a register: forced
    singleScan();
    EXPECT_EQ(ladder()->outputExplanation(), QStringLiteral("M0.0 is on through I0.0, R0.1 > 4"));
}

} // namespace
