// SPDX-License-Identifier: GPL-3.0-or-later
#include "WindowTest.h"

#include "DialogDriver.h"
#include "FormInput.h"
#include "document/ProjectDocument.h"
#include "pages/AsiOptionsPage.h"
#include "pages/AsiProfileDialog.h"
#include "shell/ProjectTree.h"

#include <QAction>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QTest>

#include <gtest/gtest.h>

namespace {

using rs::ui::PageRef;

const QByteArray kAsiProject = "$name Conveyor\n"
                               "! id_pluto_ASi:00=000000000000\n"
                               "! id_pluto:01=000000000001\n"
                               "! type_pluto:00=ASi,is3\n"
                               "! type_pluto:01=A20,is3\n"
                               "! pgm_pluto:00\n"
                               "S0.0_0\n"
                               "M0.1 = ASi0.3\n"
                               "! pgm_pluto:01\n"
                               "S1.0_0\n";

// Clicks a radio button on its indicator, where a user aims.
void clickRadio(QRadioButton* button) {
    QTest::mouseClick(button, Qt::LeftButton, {}, QPoint(6, button->height() / 2));
}

bool offers(QComboBox* combo, const QString& text) {
    const int index = combo->findText(text);
    auto* model = qobject_cast<QStandardItemModel*>(combo->model());
    return index >= 0 && model->item(index)->isEnabled();
}

class AsiOptionsPageTest : public WindowTest {
protected:
    void SetUp() override {
        WindowTest::SetUp();
        ASSERT_TRUE(window.loadFile(writeFile(QStringLiteral("asi.sps"), kAsiProject)).isEmpty());
        showWindow();
    }
    void undo() { action("undoAction")->trigger(); }
    void redo() { action("redoAction")->trigger(); }
};

TEST_F(AsiOptionsPageTest, OnlyAnAsiUnitHasThePage) {
    EXPECT_NE(window.projectTree()->itemFor({PageRef::Kind::AsiOptions, document(), 0}), nullptr);
    EXPECT_EQ(window.projectTree()->itemFor({PageRef::Kind::AsiOptions, document(), 1}), nullptr);
}

TEST_F(AsiOptionsPageTest, ASafeInputSlaveIsDefinedAsTheManualShowsAndUndone) {
    clickNode({PageRef::Kind::AsiOptions, document(), 0});
    ASSERT_EQ(window.currentPage().kind, PageRef::Kind::AsiOptions);
    rs::ui::AsiOptionsPage& page = *window.asiOptionsPage();
    auto* type = child<QComboBox>(page, QStringLiteral("asiType:3"));
    auto* monitoring = child<QComboBox>(page, QStringLiteral("asiMonitoring:3"));
    auto* timeLimit = child<QDoubleSpinBox>(page, QStringLiteral("asiTimeLimit:3"));
    auto* profile = child<QPushButton>(page, QStringLiteral("asiProfile:3"));
    EXPECT_EQ(type->currentText(), QStringLiteral("Undefined"));
    EXPECT_TRUE(monitoring->isHidden()); // an undefined slave's cells are empty

    choose(type, QStringLiteral("Safe Input"));
    EXPECT_TRUE(projectText().contains(";@asi_slave ASi0.3 type=\"safe_input\" model=\"General\" "
                                       "param=\"F\" profile=\"S-0.B.F\" id1=\"F\" "
                                       "monitoring=\"channel\"\n"));
    EXPECT_FALSE(monitoring->isHidden());
    EXPECT_EQ(profile->text(), QStringLiteral("S-0.B.F ID1=F"));
    EXPECT_TRUE(timeLimit->isHidden()); // channel monitoring has no time limit

    choose(monitoring, QStringLiteral("Simultaneously"));
    EXPECT_FALSE(timeLimit->isHidden());
    timeLimit->setValue(0.25);
    EXPECT_TRUE(projectText().contains("monitoring=\"simultaneous\" time_limit_ms=\"250\"\n"));

    // A URAX other than URAX-C1 monitors its own channels: the choice is taken away.
    choose(child<QComboBox>(page, QStringLiteral("asiModel:3")), QStringLiteral("URAX-A1R"));
    EXPECT_FALSE(monitoring->isEnabled());
    EXPECT_EQ(monitoring->currentText(), QStringLiteral("No channel monitoring"));
    EXPECT_TRUE(profile->isHidden());

    undo();
    EXPECT_TRUE(projectText().contains("time_limit_ms=\"250\""));
    EXPECT_TRUE(monitoring->isEnabled());
    undo();
    undo();
    undo();
    EXPECT_FALSE(projectText().contains(";@asi_slave"));
    EXPECT_EQ(type->currentText(), QStringLiteral("Undefined"));
    for (int i = 0; i < 4; ++i)
        redo();
    EXPECT_TRUE(projectText().contains("model=\"URAX-A1R\""));
}

TEST_F(AsiOptionsPageTest, ABSlavesShareAnAddressAndNothingElseDoes) {
    clickNode({PageRef::Kind::AsiOptions, document(), 0});
    rs::ui::AsiOptionsPage& page = *window.asiOptionsPage();
    auto* a = child<QComboBox>(page, QStringLiteral("asiType:5"));
    auto* b = child<QComboBox>(page, QStringLiteral("asiType:5B"));
    EXPECT_FALSE(offers(b, QStringLiteral("Safe Input"))); // never on a B address
    choose(a, QStringLiteral("Nonsafe A"));
    choose(b, QStringLiteral("Nonsafe B"));
    EXPECT_TRUE(projectText().contains(";@asi_slave ASi0.5 type=\"nonsafe_ab\""));
    EXPECT_TRUE(projectText().contains(";@asi_slave ASi0.5B type=\"nonsafe_ab\""));
    // A safe input fills the address: the B slave goes, and its row takes nothing.
    choose(a, QStringLiteral("Safe Input"));
    EXPECT_FALSE(projectText().contains("ASi0.5B"));
    EXPECT_FALSE(b->isEnabled());
    undo();
    EXPECT_TRUE(projectText().contains(";@asi_slave ASi0.5B type=\"nonsafe_ab\""));
    EXPECT_EQ(b->currentText(), QStringLiteral("Nonsafe B"));
}

TEST_F(AsiOptionsPageTest, TheBusModeAndTheProfileDialog) {
    clickNode({PageRef::Kind::AsiOptions, document(), 0});
    rs::ui::AsiOptionsPage& page = *window.asiOptionsPage();
    auto* address = child<QSpinBox>(page, QStringLiteral("asiSlaveAddress"));
    EXPECT_FALSE(address->isEnabled()); // a bus master has no slave address of its own
    clickRadio(child<QRadioButton>(page, QStringLiteral("asiMode:monitor_slave")));
    EXPECT_TRUE(address->isEnabled());
    address->setValue(9);
    // The keyboard reaches the other group too.
    auto* immunity = child<QRadioButton>(page, QStringLiteral("asiOptimize:immunity"));
    immunity->setFocus();
    QTest::keyClick(immunity, Qt::Key_Space);
    EXPECT_TRUE(projectText().contains(
        ";@asi 00 mode=\"monitor_slave\" address=\"9\" optimize=\"immunity\"\n"));

    choose(child<QComboBox>(page, QStringLiteral("asiType:7")), QStringLiteral("Nonsafe Std"));
    {
        DialogDriver driver({[](QDialog& dialog) {
            auto& profile = static_cast<rs::ui::AsiProfileDialog&>(dialog);
            choose(profile.digitBox(1), QStringLiteral("B (Safe slave)"));
            choose(profile.digitBox(3), QStringLiteral("6"));
            EXPECT_TRUE(dialog.findChild<QLabel*>()->text().contains(
                QStringLiteral("ASi0.7 = S-7.B.F ID1=6")));
            QTest::mouseClick(dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok),
                              Qt::LeftButton);
        }});
        QTest::mouseClick(child<QPushButton>(page, QStringLiteral("asiProfile:7")), Qt::LeftButton);
        ASSERT_TRUE(driver.done());
    }
    EXPECT_TRUE(projectText().contains(
        ";@asi_slave ASi0.7 type=\"nonsafe_std\" param=\"F\" profile=\"S-7.B.F\" id1=\"6\"\n"));
    undo(); // the profile, then the type, then the bus
    EXPECT_TRUE(projectText().contains("profile=\"S-7.0.F\" id1=\"F\""));
    undo();
    EXPECT_FALSE(projectText().contains("ASi0.7"));
    undo();
    EXPECT_TRUE(projectText().contains(";@asi 00 mode=\"monitor_slave\" address=\"9\"\n"));
    EXPECT_TRUE(child<QRadioButton>(page, QStringLiteral("asiOptimize:stop_time"))->isChecked());
}

} // namespace
