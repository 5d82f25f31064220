// SPDX-License-Identifier: GPL-3.0-or-later
// The element properties dialog from the keyboard (issue 17): Tab does not
// stop at New Variable..., and a jump is not offered a variable.
#include "ladder/ElementDialog.h"

#include <QApplication>
#include <QLineEdit>
#include <QPushButton>
#include <QTest>

#include <gtest/gtest.h>

namespace {

using rs::ladder::ElementFields;
using rs::ladder::ElementKind;

TEST(ElementDialogKeys, TabFromTheOperandPassesNewVariableBy) {
    rs::ui::ElementDialog dialog(nullptr, 0, false,
                                 ElementFields{ElementKind::NormallyOpen, "I0.1", "", false, ""});
    dialog.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&dialog));
    auto* newVariable = dialog.findChild<QPushButton*>(QStringLiteral("newVariable"));
    ASSERT_NE(newVariable, nullptr);
    EXPECT_TRUE(newVariable->isVisible());
    auto* operand = dialog.findChild<QLineEdit*>(QStringLiteral("operand"));
    operand->setFocus();
    QTest::keyClick(operand, Qt::Key_Tab);
    EXPECT_NE(QApplication::focusWidget(), newVariable);
    EXPECT_FALSE(newVariable->focusPolicy() & Qt::TabFocus);
}

TEST(ElementDialogKeys, AJumpOrASequenceResetIsOfferedNoNewVariable) {
    for (const ElementKind kind : {ElementKind::Jump, ElementKind::SequenceReset}) {
        rs::ui::ElementDialog dialog(nullptr, 0, true, ElementFields{kind, "+1", "", false, ""});
        dialog.show();
        EXPECT_FALSE(dialog.findChild<QPushButton*>(QStringLiteral("newVariable"))->isVisible())
            << static_cast<int>(kind);
    }
}

} // namespace
