// SPDX-License-Identifier: GPL-3.0-or-later
#include "WindowTest.h"

#include "DialogDriver.h"
#include "document/ProjectDocument.h"
#include "pages/UnitPage.h"

#include <QAction>
#include <QCheckBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTest>

#include <gtest/gtest.h>

namespace {

using rs::ui::PageRef;

const QByteArray kAdvancedProject = "! id_pluto:00=000000000000\n"
                                    "! id_pluto:01=000000000001\n"
                                    "! type_pluto:00=A20,is3\n"
                                    "! type_pluto:01=A20,is3\n"
                                    "! pgm_pluto:00\n"
                                    "S0.0_0\n"
                                    "Q0.14 = I1.0\n";

class AdvancedSettingsTest : public WindowTest {
protected:
    void SetUp() override {
        WindowTest::SetUp();
        ASSERT_TRUE(
            window.loadFile(writeFile(QStringLiteral("two.sps"), kAdvancedProject)).isEmpty());
        showWindow();
        clickNode({PageRef::Kind::Unit, document(), 1});
    }

    // Opens Advanced Settings and answers it with `ms` (0: back to the default).
    void setCycle(int ms) {
        DialogDriver driver({[ms](QDialog& dialog) {
            auto* set = dialog.findChild<QCheckBox*>(QStringLiteral("canCycleSet"));
            auto* cycle = dialog.findChild<QSpinBox*>(QStringLiteral("canCycleMs"));
            set->setChecked(ms != 0);
            EXPECT_EQ(cycle->isEnabled(), ms != 0);
            if (ms) {
                cycle->setFocus();
                cycle->selectAll();
                QTest::keyClicks(cycle, QString::number(ms));
            }
            QTest::mouseClick(dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok),
                              Qt::LeftButton);
        }});
        QTest::mouseClick(window.findChild<QPushButton*>(QStringLiteral("advancedSettingsButton")),
                          Qt::LeftButton);
        ASSERT_TRUE(driver.done());
    }

    QString cycleText() {
        return window.findChild<QLabel*>(QStringLiteral("canCycleLabel"))->text();
    }
};

TEST_F(AdvancedSettingsTest, TheCanBusCycleTimeIsSetShownAndUndone) {
    EXPECT_EQ(cycleText(), QStringLiteral("the unit's default"));
    setCycle(40);
    EXPECT_TRUE(
        projectText().contains("! id_pluto:01=000000000001\n;@unit 01 can_cycle_ms=\"40\"\n"));
    EXPECT_EQ(cycleText(), QStringLiteral("40 ms"));
    setCycle(0);
    EXPECT_FALSE(projectText().contains("can_cycle_ms"));
    action("undoAction")->trigger();
    EXPECT_EQ(cycleText(), QStringLiteral("40 ms"));
    action("undoAction")->trigger();
    EXPECT_FALSE(projectText().contains("can_cycle_ms"));
    EXPECT_FALSE(document()->isModified());
}

} // namespace
