// SPDX-License-Identifier: GPL-3.0-or-later
#include "WindowTest.h"

#include "DialogDriver.h"
#include "output/CompileOutput.h"
#include "shell/Preferences.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QPushButton>
#include <QTest>

#include "QtPrinting.h"

#include <gtest/gtest.h>

namespace {

using PreferencesTest = WindowTest;

TEST_F(PreferencesTest, ChoicesAreKeptAndTheCompilerFollowsThem) {
    EXPECT_TRUE(rs::ui::Preferences::load() == rs::ui::Preferences::defaults());
    window.showExample();
    showWindow();
    DialogDriver driver({[](QDialog& dialog) {
        QTest::mouseClick(dialog.findChild<QCheckBox*>(QStringLiteral("warnUnconfiguredIoCheck")),
                          Qt::LeftButton);
        auto* language = dialog.findChild<QComboBox*>(QStringLiteral("languageCombo"));
        language->setCurrentIndex(language->findText(QStringLiteral("Svenska")));
        QTest::mouseClick(dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok),
                          Qt::LeftButton);
    }});
    action("preferencesAction")->trigger();
    ASSERT_TRUE(driver.done());
    const rs::ui::Preferences stored = rs::ui::Preferences::load();
    EXPECT_FALSE(stored.warnUnconfiguredIo);
    EXPECT_EQ(stored.language, QStringLiteral("sv"));

    // Without unconfigured-I/O warnings the manual's example compiles silently.
    action("compileAction")->trigger();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !window.isCompiling(); }, 30000));
    EXPECT_EQ(window.compileOutput()->rowCount(), 2); // "Compiling", closing line
}

TEST(Preferences, DefaultColoursAndValuesSurviveARoundTrip) {
    rs::ui::Preferences chosen = rs::ui::Preferences::defaults();
    chosen.ladderLinesOn = QColor(0x123456);
    chosen.screenUpdateMs = 500;
    chosen.theme = rs::ui::Preferences::Theme::Dark;
    chosen.save();
    EXPECT_TRUE(rs::ui::Preferences::load() == chosen);
    rs::ui::Preferences::defaults().save();
}

} // namespace
