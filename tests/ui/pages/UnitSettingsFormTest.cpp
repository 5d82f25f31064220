// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/UnitSettingsForm.h"
#include "project/UnitSettings.h"

#include <QComboBox>
#include <QLineEdit>

#include <gtest/gtest.h>

// The unit page's and the New Pluto dialog's IDFIX choices (manual Part 1, 5.1).
TEST(UnitSettingsForm, IdfixProgTakesTheNumberItIsWrittenWith) {
    rs::ui::UnitSettingsForm form;
    rs::project::UnitSettings settings;
    settings.idfix = "0000ABCD1234";
    settings.idfixProg = true;
    form.setSettings(settings, {0}, true);
    auto* kind = form.findChild<QComboBox*>(QStringLiteral("idfixKindCombo"));
    auto* number = form.findChild<QLineEdit*>(QStringLiteral("idfixEdit"));
    EXPECT_EQ(kind->currentText(), QStringLiteral("IDFIX-PROG"));
    EXPECT_TRUE(number->isEnabled());
    EXPECT_EQ(number->text(), QStringLiteral("0000ABCD1234"));
    EXPECT_EQ(form.settings(), settings);

    number->setText(QStringLiteral("0000AB"));
    EXPECT_FALSE(form.problem().isEmpty());
    kind->setCurrentIndex(kind->findText(QStringLiteral("No IDFIX")));
    EXPECT_FALSE(number->isEnabled());
    EXPECT_TRUE(form.problem().isEmpty());
    EXPECT_FALSE(form.settings().idfixProg);
    EXPECT_EQ(form.settings().idfix, "000000000000");
}
