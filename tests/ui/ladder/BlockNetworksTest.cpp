// SPDX-License-Identifier: GPL-3.0-or-later
// Block networks on the ladder page, used as a user does: inserted by key
// from the project's libraries, bound in the pins dialog, edited, copied,
// updated and undone; the project text is the judge.
#include "WindowTest.h"

#include "DialogDriver.h"
#include "document/ProjectDocument.h"
#include "ladder/LadderPage.h"
#include "ladder/LadderView.h"
#include "ladder/NetworkItem.h"
#include "project/UnitText.h"
#include "shell/PageRef.h"

#include <QAction>
#include <QDialog>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QTableWidget>
#include <QTest>
#include <QUndoStack>

#include "QtPrinting.h"

#include <gtest/gtest.h>

namespace {

using rs::ui::LadderPage;
using rs::ui::PageRef;

const QByteArray kDoors = "! id_pluto:00=000000000000\n"
                          "! type_pluto:00=A20,is3\n"
                          "! I0.0=Door1A\n"
                          "! I0.1=Door1B\n"
                          "! pgm_pluto:00\n"
                          "S0.0_0\n"
                          "Q0.5 = I0.5\n"
                          ";@block EquivalentInputs Channel1=\"Door1A\" Channel2=\"Door1B\" "
                          "Out=\"Q0.2\"\n"
                          ";@end\n";

const QByteArray kEmpty = "! id_pluto:00=000000000000\n"
                          "! type_pluto:00=A20,is3\n"
                          "! I0.0=Door1A\n"
                          "! pgm_pluto:00\n"
                          "S0.0_0\n"
                          "Q0.5 = I0.5\n";

class BlockNetworksTest : public WindowTest {
protected:
    LadderPage& page() { return *window.ladderPage(); }

    void openLadder(const QByteArray& text) {
        ASSERT_TRUE(window.loadFile(writeFile(QStringLiteral("doors.sps"), text)).isEmpty());
        showWindow();
        clickNode({PageRef::Kind::Ladder, document(), 0, 0});
        page().view()->setFocus();
    }

    QByteArray unitText() {
        return QByteArray::fromStdString(rs::project::unitText(document()->project(), 0));
    }

    static void typeInto(QDialog& dialog, const QString& name, const QString& text) {
        auto* field = dialog.findChild<QLineEdit*>(name);
        ASSERT_NE(field, nullptr) << name.toStdString();
        field->selectAll();
        QTest::keyClick(field, Qt::Key_Backspace);
        QTest::keyClicks(field, text);
    }

    // The pins dialog's message, after OK was pressed.
    static QString problemOf(QDialog& dialog) {
        return dialog.findChild<QLabel*>(QStringLiteral("problem"))->text();
    }
};

TEST_F(BlockNetworksTest, AnOpenedInstanceIsOneBoxWithItsPins) {
    openLadder(kDoors);
    ASSERT_EQ(page().networkCount(0), 2);
    const auto& layout = page().networkItem(0, 1)->layout();
    ASSERT_TRUE(layout.block.has_value());
    EXPECT_EQ(layout.block->type, QStringLiteral("EquivalentInputs"));
    ASSERT_EQ(layout.block->pins.size(), 5U);
    EXPECT_TRUE(layout.block->pins[0].power);
    EXPECT_EQ(layout.block->pins[0].name, QStringLiteral("Door1A"));
    EXPECT_EQ(layout.block->pins[2].operand, QStringLiteral("(0s50)"))
        << "DiscrepancyTime is open and takes its default";
    EXPECT_TRUE(layout.block->pins[4].operand.isEmpty()) << "Fault may stay open";
    const std::set<rs::lang::Address> watched = page().pinVariables();
    EXPECT_EQ(watched.size(), 3U) << "Door1A, Door1B and Q0.2 show live values";
}

TEST_F(BlockNetworksTest, InsertedByKeyFilteredBoundAndUndoneAsOneStep) {
    openLadder(kEmpty);
    page().setCursor({0, 0, std::nullopt, std::nullopt, -1});
    const QByteArray before = unitText();
    DialogDriver driver(
        {[](QDialog& chooser) {
             auto* list = chooser.findChild<QListWidget*>(QStringLiteral("blocks"));
             ASSERT_NE(list, nullptr);
             const int all = list->count();
             typeInto(chooser, QStringLiteral("filter"), QStringLiteral("equiv"));
             EXPECT_LT(list->count(), all);
             ASSERT_GE(list->count(), 1);
             EXPECT_TRUE(
                 list->currentItem()->text().startsWith(QStringLiteral("EquivalentInputs")));
             QTest::keyClick(chooser.findChild<QLineEdit*>(QStringLiteral("filter")),
                             Qt::Key_Return);
         },
         [](QDialog& pins) {
             typeInto(pins, QStringLiteral("pin_Channel1"), QStringLiteral("door1a"));
             typeInto(pins, QStringLiteral("pin_Channel2"), QStringLiteral("I0.1"));
             typeInto(pins, QStringLiteral("pin_Out"), QStringLiteral("I0.7"));
             pins.accept();
             EXPECT_TRUE(pins.isVisible()) << "an input cannot be the output";
             EXPECT_TRUE(problemOf(pins).contains(QStringLiteral("pin Out takes")))
                 << problemOf(pins).toStdString();
             typeInto(pins, QStringLiteral("pin_Out"), QStringLiteral("Q0.2"));
             pins.accept();
         }});
    QTest::keyClick(page().view(), Qt::Key_F, Qt::ShiftModifier);
    ASSERT_TRUE(driver.done());
    const QByteArray text = unitText();
    EXPECT_TRUE(
        text.contains(";@block EquivalentInputs Channel1=\"door1a\" Channel2=\"I0.1\" "
                      "Out=\"Q0.2\" lib=\"Rungsmith_Basics\" version=\"1.0\" #pin.Fault=\"M0."))
        << text.toStdString();
    EXPECT_TRUE(text.contains("Q0.2 = Door1A * I0.1 * /M0.")) << text.toStdString();
    ASSERT_EQ(page().networkCount(0), 2);
    EXPECT_TRUE(page().networkItem(0, 1)->layout().block.has_value());
    EXPECT_EQ(page().cursor().network, 1);

    document()->undoStack()->undo();
    EXPECT_EQ(unitText(), before);
    EXPECT_EQ(page().networkCount(0), 1);
    document()->undoStack()->redo();
    EXPECT_EQ(unitText(), text);
}

TEST_F(BlockNetworksTest, EnterOnTheBoxRebindsItsPinsKeepingItsPrivateVariables) {
    openLadder(kDoors);
    const QByteArray before = unitText();
    const auto record = before.indexOf(";@block");
    const QByteArray fault = before.mid(before.indexOf("#fault=", record), 18);
    page().setCursor({0, 1, std::nullopt, std::nullopt, -1});
    DialogDriver driver({[](QDialog& pins) {
        typeInto(pins, QStringLiteral("pin_DiscrepancyTime"), QStringLiteral("1s00"));
        pins.accept();
    }});
    QTest::keyClick(page().view(), Qt::Key_Return);
    ASSERT_TRUE(driver.done());
    const QByteArray text = unitText();
    EXPECT_TRUE(text.contains("DiscrepancyTime=\"1s00\"")) << text.toStdString();
    EXPECT_TRUE(text.contains("TON(1s00)")) << text.toStdString();
    EXPECT_TRUE(text.contains(fault)) << fault.toStdString() << "\n" << text.toStdString();
    EXPECT_EQ(page().networkItem(0, 1)->layout().block->pins[2].operand, QStringLiteral("1s00"));
    document()->undoStack()->undo();
    EXPECT_EQ(unitText(), before);
}

TEST_F(BlockNetworksTest, ACopiedInstanceIsPastedWithPrivateVariablesOfItsOwn) {
    openLadder(kDoors);
    page().setCursor({0, 1, std::nullopt, std::nullopt, -1});
    page().copyNetworks();
    page().pasteNetworks();
    ASSERT_EQ(page().networkCount(0), 3);
    EXPECT_TRUE(page().networkItem(0, 2)->layout().block.has_value());
    const QByteArray text = unitText();
    QList<QByteArray> faults;
    for (qsizetype at = text.indexOf("#fault="); at >= 0; at = text.indexOf("#fault=", at + 1))
        faults << text.mid(at, text.indexOf(' ', at) - at);
    ASSERT_EQ(faults.size(), 2) << text.toStdString();
    EXPECT_NE(faults[0], faults[1]) << "instances never share state";
    document()->undoStack()->undo();
    EXPECT_EQ(page().networkCount(0), 2);
}

TEST_F(BlockNetworksTest, StatementsEditedByHandShowAsOrdinaryNetworks) {
    openLadder(kDoors);
    ASSERT_TRUE(page().networkItem(0, 1)->layout().block.has_value());
    document()->edit(QStringLiteral("Edit"), [](rs::project::Project& project) {
        for (auto& line : project.program.units[0].steps[0].lines)
            if (auto* statement = std::get_if<rs::lang::Statement>(&line.body);
                statement && statement->target.address.index == 2)
                statement->target.address.index = 3; // Q0.2 -> Q0.3
    });
    ASSERT_TRUE(unitText().contains("Q0.3 = Door1A")) << unitText().toStdString();
    for (int n = 0; n < page().networkCount(0); ++n)
        EXPECT_FALSE(page().networkItem(0, n)->layout().block.has_value()) << n;
    EXPECT_GT(page().networkCount(0), 2) << "the statements are networks of their own";
}

TEST_F(BlockNetworksTest, AnInstanceOfAnotherVersionSaysSoAndUpdatesAsOneStep) {
    openLadder(kDoors);
    document()->edit(QStringLiteral("Older"), [](rs::project::Project& project) {
        auto& record =
            std::get<rs::lang::CommentLine>(project.program.units[0].steps[0].lines[1].body);
        record.text.replace(record.text.find("version=\"1.0\""), 13, "version=\"0.9\"");
    });
    ASSERT_TRUE(page().networkItem(0, 1)->layout().block.has_value());
    bool noted = false;
    for (const auto& text : page().networkItem(0, 1)->layout().texts)
        noted = noted || text.text.contains(QStringLiteral("version 0.9"));
    EXPECT_TRUE(noted);
    page().setCursor({0, 1, std::nullopt, std::nullopt, -1});
    QAction* update = page().action(QStringLiteral("updateBlockAction"));
    ASSERT_NE(update, nullptr);
    const QByteArray older = unitText();
    update->trigger();
    EXPECT_TRUE(unitText().contains("version=\"1.0\"")) << unitText().toStdString();
    EXPECT_EQ(page().blockStatus(0, 1)->standing, rs::blocks::Standing::AsMade);
    document()->undoStack()->undo();
    EXPECT_EQ(unitText(), older);
}

TEST_F(BlockNetworksTest, ABlockNetworkRefusesARungAndSaysWhy) {
    openLadder(kDoors);
    page().setCursor({0, 1, std::nullopt, std::nullopt, -1});
    const QByteArray before = unitText();
    DialogDriver driver({[](QDialog& dialog) {
        typeInto(dialog, QStringLiteral("operand"), QStringLiteral("Q0.6"));
        dialog.accept();
    }});
    QTest::keyClick(page().view(), Qt::Key_L);
    ASSERT_TRUE(driver.done());
    EXPECT_EQ(unitText(), before);
    EXPECT_TRUE(page().message().contains(QStringLiteral("block")))
        << page().message().toStdString();
}

TEST_F(BlockNetworksTest, ABadCallIsSavedAsItIsAndIsMendedInItsPinsDialog) {
    QByteArray bad = kDoors;
    bad.replace("Out=\"Q0.2\"", "Out=\"I0.5\"");
    openLadder(bad);
    const QString path = document()->path();
    const QByteArray before = unitText();
    ASSERT_TRUE(before.contains("Out=\"I0.5\"\n;@end")) << before.toStdString();
    action("saveAction")->trigger();
    EXPECT_EQ(readFile(path), bad) << "a file with a bad call loses nothing on save";

    ASSERT_EQ(page().networkCount(0), 2);
    ASSERT_TRUE(page().networkItem(0, 1)->layout().block.has_value())
        << "the call waits for its statements as a box, to be bound anew";
    page().setCursor({0, 1, std::nullopt, std::nullopt, -1});
    DialogDriver driver({[](QDialog& pins) {
        typeInto(pins, QStringLiteral("pin_Out"), QStringLiteral("Q0.2"));
        pins.accept();
    }});
    QTest::keyClick(page().view(), Qt::Key_Return);
    ASSERT_TRUE(driver.done());
    EXPECT_TRUE(unitText().contains("Q0.2 = Door1A * Door1B * /M0.")) << unitText().toStdString();
    EXPECT_EQ(page().blockStatus(0, 1)->standing, rs::blocks::Standing::AsMade);
}

TEST_F(BlockNetworksTest, MakeBlockTurnsNetworksIntoALibraryBlockAndAnInstance) {
    const QByteArray text = "! id_pluto:00=000000000000\n"
                            "! type_pluto:00=A20,is3\n"
                            "! I0.0=Start\n"
                            "! pgm_pluto:00\n"
                            "S0.0_0\n"
                            "M0.5 = Start * (I0.1 + M0.5)\n"
                            "Q0.2 = M0.5 * TON(0s30)\n"
                            "Q0.3 = I0.4\n";
    openLadder(text);
    ASSERT_EQ(page().networkCount(0), 3);
    QWidget* viewport = page().view()->viewport();
    const auto at = [&](int network) {
        return page().view()->mapFromScene(
            page().networkItem(0, network)->sceneBoundingRect().topLeft() + QPointF(60, 12));
    };
    QTest::mouseClick(viewport, Qt::LeftButton, {}, at(0));
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::ShiftModifier, at(1));
    DialogDriver driver({[](QDialog& dialog) {
        typeInto(dialog, QStringLiteral("blockName"), QStringLiteral("DelayedLatch"));
        typeInto(dialog, QStringLiteral("description"), QStringLiteral("A latch and a lamp."));
        auto* pins = dialog.findChild<QTableWidget*>(QStringLiteral("pins"));
        ASSERT_NE(pins, nullptr);
        ASSERT_EQ(pins->rowCount(), 4) << "Start, I0.1, Q0.2 and the private M0.5";
        EXPECT_EQ(pins->item(3, 0)->text(), QStringLiteral("M0_5"));
        pins->item(2, 0)->setText(QStringLiteral("Lamp"));
        dialog.accept();
    }});
    page().action(QStringLiteral("makeBlockAction"))->trigger();
    ASSERT_TRUE(driver.done());
    const QByteArray made = unitText();
    EXPECT_TRUE(made.contains(";@block DelayedLatch Start=\"Start\" I0_1=\"I0.1\" Lamp=\"Q0.2\" "
                              "lib=\"doors_Blocks\" version=\"1.0\" #M0_5=\"M0.5\"\n"
                              "M0.5 = Start * (I0.1 + M0.5)\nQ0.2 = M0.5 * TON(0s30)\n;@end\n"))
        << made.toStdString();
    ASSERT_EQ(page().networkCount(0), 2);
    EXPECT_TRUE(page().networkItem(0, 0)->layout().block.has_value());
    EXPECT_EQ(page().blockStatus(0, 0)->standing, rs::blocks::Standing::AsMade);
    const QByteArray library = readFile(directory.filePath(QStringLiteral("doors_Blocks.rslib")));
    EXPECT_TRUE(library.contains("block DelayedLatch")) << library.toStdString();
    EXPECT_TRUE(library.contains("body {Lamp} = {#M0_5} * TON(0s30)")) << library.toStdString();

    // The F list offers it now.
    DialogDriver chooser({[](QDialog& dialog) {
        typeInto(dialog, QStringLiteral("filter"), QStringLiteral("DelayedLatch"));
        EXPECT_EQ(dialog.findChild<QListWidget*>(QStringLiteral("blocks"))->count(), 1);
        dialog.reject();
    }});
    page().insertBlock();
    EXPECT_TRUE(chooser.done());

    document()->undoStack()->undo();
    EXPECT_EQ(page().networkCount(0), 3);
    EXPECT_FALSE(unitText().contains(";@block"));
}

} // namespace
