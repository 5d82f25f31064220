// SPDX-License-Identifier: GPL-3.0-or-later
#include "ReviewWindowTest.h"

#include "document/ProjectDocument.h"
#include "ladder/LadderPage.h"
#include "ladder/NetworkItem.h"

#include <QAction>
#include <QDialog>
#include <QLabel>
#include <QTest>

#include <gtest/gtest.h>

#include <map>
#include <utility>

namespace {

using rs::ui::PageRef;

class ChangesSinceValidationTest : public ReviewWindowTest {
protected:
    void SetUp() override {
        ReviewWindowTest::SetUp();
        date = markValidated();
    }

    QString sinceValidation() {
        auto* label = window.findChild<QLabel*>(QStringLiteral("sinceValidationLabel"));
        EXPECT_NE(label, nullptr);
        if (!label)
            return {};
        EXPECT_TRUE(QTest::qWaitFor(
            [&] { return !label->text().startsWith(QStringLiteral("computing")); }, 30000));
        return label->text();
    }

    QString date;
};

// Issue 18: the project page says whether the project changed since it was
// validated, and in which units.
TEST_F(ChangesSinceValidationTest, TheProjectPageNamesTheUnitsChangedSinceValidation) {
    ASSERT_TRUE(window.showPage(PageRef::Kind::Project, 0));
    EXPECT_EQ(sinceValidation(),
              QStringLiteral("no change in behaviour since validation on ") + date);

    changeUnitOne();
    const QString said = sinceValidation();
    EXPECT_TRUE(said.startsWith(QStringLiteral("changed since validation on ") + date))
        << said.toStdString();
    EXPECT_TRUE(said.contains(QStringLiteral("Pluto 1"))) << said.toStdString();
    EXPECT_FALSE(said.contains(QStringLiteral("Pluto 0 "))) << said.toStdString();
    EXPECT_TRUE(said.contains(QStringLiteral("2 networks"))) << said.toStdString();

    // Undone, nothing has changed again; without a baseline the line goes.
    document()->undoStack()->undo();
    EXPECT_EQ(sinceValidation(),
              QStringLiteral("no change in behaviour since validation on ") + date);
    document()->undoStack()->undo();
    EXPECT_FALSE(document()->project().baseline.has_value());
    EXPECT_FALSE(window.findChild<QLabel*>(QStringLiteral("sinceValidationLabel"))->isVisible());
}

// Issue 18: the ladder marks each network changed or added since validation
// with a bar in its margin, which says so under the mouse.
TEST_F(ChangesSinceValidationTest, TheLadderMarksNetworksChangedSinceValidation) {
    ASSERT_TRUE(window.showPage(PageRef::Kind::Ladder, 1));
    auto* page = window.findChild<rs::ui::LadderPage*>();
    ASSERT_NE(page, nullptr);
    ASSERT_EQ(page->networkCount(0), 2);
    changeUnitOne();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !page->changedSinceValidation().empty(); }, 30000));
    const std::map<std::pair<int, int>, bool> expected{{{0, 1}, false}, {{0, 2}, true}};
    EXPECT_EQ(page->changedSinceValidation(), expected);

    const rs::ui::NetworkItem* changed = page->networkItem(0, 1);
    EXPECT_EQ(changed->validationNote(QPointF(3, 10)),
              QStringLiteral("Changed since validation on ") + date);
    EXPECT_EQ(page->networkItem(0, 2)->validationNote(QPointF(3, 10)),
              QStringLiteral("Added since validation on ") + date);
    EXPECT_TRUE(changed->validationNote(QPointF(60, 10)).isEmpty()); // not on the bar
    EXPECT_TRUE(page->networkItem(0, 0)->validationNote(QPointF(3, 10)).isEmpty());

    // Back as validated, no bar is left.
    document()->undoStack()->undo();
    ASSERT_TRUE(QTest::qWaitFor([&] { return page->changedSinceValidation().empty(); }, 30000));
}

} // namespace
