// SPDX-License-Identifier: GPL-3.0-or-later
// The ladder's dialogs from the keyboard alone (issue 17): Tab does not stop
// at New Variable..., a jump is not offered a variable, one Return or Escape
// does what it says with the completion list open, and the network comment is
// confirmed with Ctrl+Return.
#include "DialogDriver.h"
#include "document/ProjectDocument.h"
#include "ladder/ConfigOptionDialog.h"
#include "ladder/ElementDialog.h"
#include "ladder/NetworkCommentDialog.h"
#include "project/ProjectFile.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QCompleter>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
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

rs::project::Project namedProject() {
    return rs::project::readProject("$name Keys\n"
                                    "! id_pluto:00=000000000000\n"
                                    "! type_pluto:00=A20,is2\n"
                                    "! I0.1=StartButton\n"
                                    "! I0.2=StopButton\n"
                                    "! pgm_pluto:00\n"
                                    "S0.0_0\n"
                                    "Q0.2 = I0.1\n")
        .project;
}

// Types "Start" so that the completion list opens, and chooses its first line.
QCompleter* openCompletion(QLineEdit* operand) {
    operand->setFocus();
    operand->clear();
    QTest::keyClicks(operand, QStringLiteral("Start"));
    QCompleter* completer = operand->completer();
    if (!completer || !completer->popup()->isVisible())
        return nullptr;
    QTest::keyClick(completer->popup(), Qt::Key_Down);
    return completer;
}

TEST(ElementDialogKeys, WithTheCompletionListOpenOneReturnTakesTheNameAndConfirms) {
    rs::ui::ProjectDocument document(namedProject());
    rs::ui::ElementDialog dialog(&document, 0, false,
                                 ElementFields{ElementKind::NormallyOpen, "", "", false, ""});
    dialog.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&dialog));
    auto* operand = dialog.findChild<QLineEdit*>(QStringLiteral("operand"));
    QCompleter* completer = openCompletion(operand);
    ASSERT_NE(completer, nullptr);
    QTest::keyClick(completer->popup(), Qt::Key_Return);
    EXPECT_EQ(dialog.result(), QDialog::Accepted);
    EXPECT_FALSE(dialog.isVisible());
    EXPECT_EQ(operand->text(), QStringLiteral("StartButton"));
    EXPECT_TRUE(dialog.element().has_value());
}

TEST(ElementDialogKeys, WithTheCompletionListOpenOneEscapeCancels) {
    rs::ui::ProjectDocument document(namedProject());
    rs::ui::ElementDialog dialog(&document, 0, false,
                                 ElementFields{ElementKind::NormallyOpen, "", "", false, ""});
    dialog.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&dialog));
    QCompleter* completer = openCompletion(dialog.findChild<QLineEdit*>(QStringLiteral("operand")));
    ASSERT_NE(completer, nullptr);
    QTest::keyClick(completer->popup(), Qt::Key_Escape);
    EXPECT_EQ(dialog.result(), QDialog::Rejected);
    EXPECT_FALSE(dialog.isVisible());
}

TEST(NetworkCommentKeys, TabLeavesTheTextAndCtrlReturnConfirms) {
    rs::ui::NetworkCommentDialog dialog(QStringLiteral("Comment:"), QStringLiteral("first"));
    dialog.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&dialog));
    QPlainTextEdit* editor = dialog.editor();
    editor->setFocus();
    QTest::keyClick(editor, Qt::Key_Return);
    QTest::keyClicks(editor, QStringLiteral("second"));
    QTest::keyClick(editor, Qt::Key_Tab);
    EXPECT_EQ(dialog.text(), QStringLiteral("first\nsecond"));
    EXPECT_NE(QApplication::focusWidget(), editor);
    EXPECT_TRUE(dialog.isVisible());

    editor->setFocus();
    QTest::keyClick(editor, Qt::Key_Return, Qt::ControlModifier);
    EXPECT_EQ(dialog.result(), QDialog::Accepted);
    EXPECT_EQ(dialog.text(), QStringLiteral("first\nsecond\n").chopped(1));
}

// Issue 17, finding 7: a refusal grows its dialog and covers nothing.
void expectProblemShownWhole(QDialog& dialog) {
    auto* problem = dialog.findChild<QLabel*>(QStringLiteral("problem"));
    ASSERT_NE(problem, nullptr);
    EXPECT_TRUE(problem->isVisible());
    EXPECT_FALSE(problem->text().isEmpty());
    EXPECT_GE(problem->height(), problem->heightForWidth(problem->width()));
    auto* buttons = dialog.findChild<QDialogButtonBox*>();
    ASSERT_NE(buttons, nullptr);
    EXPECT_LE(problem->geometry().bottom(), buttons->geometry().top());
    for (auto* field : dialog.findChildren<QLineEdit*>())
        EXPECT_FALSE(problem->geometry().intersects(field->geometry()))
            << field->objectName().toStdString();
}

TEST(DialogProblems, TheNewVariableDialogShowsItsRefusalWhole) {
    rs::ui::ProjectDocument document(namedProject());
    rs::ui::ElementDialog dialog(&document, 0, false,
                                 ElementFields{ElementKind::NormallyOpen, "", "", false, ""});
    dialog.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&dialog));
    DialogDriver driver({[](QDialog& newVariable) {
        EXPECT_EQ(newVariable.objectName(), QStringLiteral("newVariableDialog"));
        newVariable.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();
        QApplication::processEvents();
        expectProblemShownWhole(newVariable);
        newVariable.reject();
    }});
    dialog.findChild<QPushButton*>(QStringLiteral("newVariable"))->click();
    EXPECT_TRUE(driver.done());
}

TEST(DialogProblems, TheConfigOptionDialogExplainsItselfAndShowsItsRefusalWhole) {
    rs::ui::ProjectDocument document(namedProject());
    rs::ui::ConfigOptionDialog dialog(&document, 0, rs::ladder::ConfigOption{});
    dialog.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&dialog));
    auto* description = dialog.findChild<QLineEdit*>(QStringLiteral("description"));
    EXPECT_GE(description->width(), description->fontMetrics().averageCharWidth() * 40);
    dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();
    QApplication::processEvents();
    EXPECT_TRUE(dialog.isVisible());
    expectProblemShownWhole(dialog);
}

} // namespace
