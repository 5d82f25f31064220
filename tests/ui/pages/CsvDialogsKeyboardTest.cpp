// SPDX-License-Identifier: GPL-3.0-or-later
// The CSV dialogs from the keyboard: every label with a mnemonic leads to its
// field (issue 17: "&File:" showed its ampersand and Alt+F did nothing).
#include "pages/CsvExportDialog.h"
#include "pages/CsvImportDialog.h"
#include "project/ProjectFile.h"

#include <QLabel>
#include <QLineEdit>

#include <gtest/gtest.h>

namespace {

void expectEveryMnemonicHasABuddy(const QDialog& dialog) {
    int mnemonics = 0;
    for (const QLabel* label : dialog.findChildren<QLabel*>()) {
        if (!label->text().contains(QLatin1Char('&')))
            continue;
        ++mnemonics;
        EXPECT_NE(label->buddy(), nullptr) << label->text().toStdString();
    }
    EXPECT_GT(mnemonics, 0);
}

QLineEdit* buddyOf(const QDialog& dialog, const QString& text) {
    for (const QLabel* label : dialog.findChildren<QLabel*>())
        if (label->text() == text)
            return qobject_cast<QLineEdit*>(label->buddy());
    return nullptr;
}

TEST(CsvDialogsKeyboard, TheFileLabelLeadsToThePath) {
    const rs::ui::CsvExportDialog exportDialog(0, QStringLiteral("/tmp/names.csv"));
    expectEveryMnemonicHasABuddy(exportDialog);
    QLineEdit* exportPath = buddyOf(exportDialog, QStringLiteral("&File:"));
    ASSERT_NE(exportPath, nullptr);
    EXPECT_EQ(exportPath->objectName(), QStringLiteral("csvPathEdit"));

    const rs::project::Project project =
        rs::project::readProject("! id_pluto:00=000000000000\n! pgm_pluto:00\n").project;
    const rs::ui::CsvImportDialog importDialog(project, 0);
    expectEveryMnemonicHasABuddy(importDialog);
    QLineEdit* importPath = buddyOf(importDialog, QStringLiteral("&File:"));
    ASSERT_NE(importPath, nullptr);
    EXPECT_EQ(importPath->objectName(), QStringLiteral("csvPathEdit"));
}

} // namespace
