// SPDX-License-Identifier: GPL-3.0-or-later
#include "ReviewWindowTest.h"

#include "document/ProjectDocument.h"
#include "ladder/LadderPage.h"
#include "review/CompareDialog.h"

#include <QAction>
#include <QApplication>
#include <QFile>
#include <QListWidget>
#include <QPushButton>
#include <QTest>

#include <gtest/gtest.h>

namespace {

using rs::ui::CompareDialog;
using rs::ui::PageRef;

const QString kComparePressLine =
    QStringLiteral(RUNGSMITH_SOURCE_DIR "/resources/examples/press-line.sps");

class CompareDialogTest : public ReviewWindowTest {
protected:
    // The dialog Compare With or Compare With Validated opened, once compared.
    CompareDialog* openedDialog() {
        auto* dialog = window.findChild<CompareDialog*>();
        EXPECT_NE(dialog, nullptr);
        if (dialog) {
            EXPECT_TRUE(QTest::qWaitFor([&] { return !dialog->isComparing(); }, 30000));
        }
        QApplication::processEvents();
        return dialog;
    }

    // Project > Compare With..., once the file is chosen.
    CompareDialog* compareWithFile(const QString& old) {
        window.openComparison(document(), old);
        return openedDialog();
    }
};

// Issue 18: Project > Compare With... lists what `rungsmith-cli diff` lists,
// in the window's words, and says whether the behaviour changed.
TEST_F(CompareDialogTest, ListsTheChangedNetworksAndTheVerdict) {
    changeUnitOne();
    CompareDialog* dialog = compareWithFile(kComparePressLine);
    ASSERT_NE(dialog, nullptr);
    EXPECT_EQ(dialog->lines(), (QStringList{QStringLiteral("Pluto 01 S1.0_0 network 2: changed"),
                                            QStringLiteral("Pluto 01 S1.0_0 network 3: added")}));
    EXPECT_TRUE(dialog->verdict().startsWith(QStringLiteral("Behaviour changed in Pluto 01 (")))
        << dialog->verdict().toStdString();
}

TEST_F(CompareDialogTest, TheSameProjectHasNoChangeInBehaviour) {
    CompareDialog* dialog = compareWithFile(kComparePressLine);
    ASSERT_NE(dialog, nullptr);
    EXPECT_EQ(dialog->lines(), QStringList{QStringLiteral("No network, unit or option differs.")});
    EXPECT_EQ(dialog->verdict(), QStringLiteral("No change in behaviour."));
}

// A side with errors cannot be compared, and the dialog says which.
TEST_F(CompareDialogTest, AnOldVersionWithErrorsIsNamed) {
    const QString broken =
        writeFile(QStringLiteral("broken.sps"),
                  readFile(kComparePressLine).replace("Q1.3 = Q1.2", "Q1.3 = I1.99"));
    CompareDialog* dialog = compareWithFile(broken);
    ASSERT_NE(dialog, nullptr);
    EXPECT_TRUE(dialog->lines().isEmpty());
    EXPECT_TRUE(dialog->verdict().contains(QStringLiteral("broken.sps has 1 error")))
        << dialog->verdict().toStdString();
    EXPECT_FALSE(
        dialog->findChild<QPushButton*>(QStringLiteral("saveReviewPdfButton"))->isEnabled());
}

// The review a reviewer signs: the PDF `diff --pdf` writes.
TEST_F(CompareDialogTest, SavesTheReviewAsPdf) {
    changeUnitOne();
    CompareDialog* dialog = compareWithFile(kComparePressLine);
    ASSERT_NE(dialog, nullptr);
    EXPECT_TRUE(
        dialog->findChild<QPushButton*>(QStringLiteral("saveReviewPdfButton"))->isEnabled());
    const QString pdf = directory.filePath(QStringLiteral("review.pdf"));
    EXPECT_EQ(dialog->savePdf(pdf), QString());
    const QByteArray written = readFile(pdf);
    EXPECT_TRUE(written.startsWith("%PDF")) << written.left(20).toStdString();
    // Two networks drawn old beside new take pages of their own after the summary.
    EXPECT_GE(written.count("/Type /Page\n") + written.count("/Type /Page "), 2);
}

// Enter on a network's line opens it in the ladder, selected.
TEST_F(CompareDialogTest, EnterOnANetworkOpensItInTheLadder) {
    changeUnitOne();
    CompareDialog* dialog = compareWithFile(kComparePressLine);
    ASSERT_NE(dialog, nullptr);
    auto* list = dialog->findChild<QListWidget*>(QStringLiteral("comparisonLines"));
    list->setCurrentRow(1);
    QTest::keyClick(list, Qt::Key_Return);
    EXPECT_EQ(window.currentPage().kind, PageRef::Kind::Ladder);
    EXPECT_EQ(window.currentPage().station, 1);
    auto* page = window.findChild<rs::ui::LadderPage*>();
    EXPECT_EQ(page->cursor().step, 0);
    EXPECT_EQ(page->cursor().network, 2);
    EXPECT_TRUE(dialog->isVisible()); // the reviewer goes on to the next one
}

// Compare With Validated is there once the project has a baseline, and lists
// what changed since; the baseline keeps no networks to draw.
TEST_F(CompareDialogTest, ComparesWithTheValidatedVersion) {
    QAction* compare = action("compareValidatedAction");
    EXPECT_FALSE(compare->isEnabled());
    markValidated();
    EXPECT_TRUE(compare->isEnabled());
    changeUnitOne();
    compare->trigger();
    CompareDialog* dialog = openedDialog();
    ASSERT_NE(dialog, nullptr);
    EXPECT_EQ(dialog->lines(), (QStringList{QStringLiteral("Pluto 01 S1.0_0 network 2: changed"),
                                            QStringLiteral("Pluto 01 S1.0_0 network 3: added")}));
    EXPECT_TRUE(dialog->verdict().startsWith(QStringLiteral("Behaviour changed in Pluto 01")));
    EXPECT_FALSE(
        dialog->findChild<QPushButton*>(QStringLiteral("saveReviewPdfButton"))->isVisible());
}

} // namespace
