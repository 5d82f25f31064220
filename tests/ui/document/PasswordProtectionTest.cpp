// SPDX-License-Identifier: GPL-3.0-or-later
#include "WindowTest.h"

#include "DialogDriver.h"
#include "MessageBoxAnswerer.h"
#include "document/ProjectDocument.h"
#include "ladder/LadderPage.h"
#include "pages/IoOptionsPage.h"
#include "pages/VariablesPage.h"
#include "project/ProjectFile.h"
#include "project/ProtectedText.h"
#include "text/ProgramEditor.h"
#include "text/TextPage.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalSpy>
#include <QTableView>
#include <QToolBar>

#include <gtest/gtest.h>

// Issue 19 (manual Part 1, 4.1): File > Password Protect, and opening a
// protected file with each of the manual's permissions.

namespace {

using rs::project::Permission;
using rs::ui::ProjectDocument;

const QByteArray kPress = "$name Press\n"
                          "! id_pluto:00=000000000000\n"
                          "! type_pluto:00=A20,is3\n"
                          "! pgm_pluto:00\n"
                          "S0.0_0\n"
                          ";@network comment=\"Door switch fitted\" option=\"on\"\n"
                          "S(M0.5)\n"
                          ";@network comment=\"Outputs\"\n"
                          "Q0.2 = I0.0 * M0.5\n"
                          "Q0.3 = I0.1\n";

const QString kMain = QStringLiteral("Kärnan 7 main");
const QString kOptions = QStringLiteral("options 12");

// kPress protected with the main password kMain, as a saved file holds it.
QByteArray sealedPress(rs::project::OptionsAccess options) {
    rs::project::Project project = rs::project::readProject(kPress.toStdString()).project;
    rs::project::NewProtection fresh = rs::project::protectWith(kMain.toStdString(), options, "");
    project.protection = fresh.record;
    return QByteArray::fromStdString(
        rs::project::sealProjectText(rs::project::writeProject(project), fresh.keys));
}

// The current project with `from` replaced by `to` in its text, as an edit would make it.
bool editText(ProjectDocument* document, const std::string& from, const std::string& to) {
    std::string text = rs::project::writeProject(document->project());
    text.replace(text.find(from), from.size(), to);
    return document->replace(QStringLiteral("Edit"), rs::project::readProject(text).project);
}

class PasswordProtectionTest : public WindowTest {
protected:
    // Opens the file, answering the question of permission as given.
    bool openWith(const QString& path, const char* permission, const QString& password) {
        DialogDriver driver({[&](QDialog& dialog) {
            dialog.findChild<QRadioButton*>(QLatin1String(permission))->setChecked(true);
            dialog.findChild<QLineEdit*>(QStringLiteral("password"))->setText(password);
            dialog.accept();
        }});
        const bool opened = openFile(path);
        EXPECT_EQ(driver.handled(), 1);
        return opened;
    }
    bool openFile(const QString& path) { return window.openFile(path); }
    void closeProject() { action("closeAction")->trigger(); }
};

TEST_F(PasswordProtectionTest, ProtectReopenWithEachPermissionAndRemove) {
    const QString path = writeFile(QStringLiteral("press.sps"), kPress);
    ASSERT_TRUE(openFile(path));
    {
        DialogDriver driver({[](QDialog& dialog) {
            dialog.findChild<QCheckBox*>(QStringLiteral("protect"))->setChecked(true);
            dialog.findChild<QLineEdit*>(QStringLiteral("password"))->setText(kMain);
            dialog.findChild<QLineEdit*>(QStringLiteral("repeat"))->setText(kMain);
            dialog.findChild<QRadioButton*>(QStringLiteral("optionsOwn"))->setChecked(true);
            dialog.findChild<QLineEdit*>(QStringLiteral("optionsPassword"))->setText(kOptions);
            dialog.findChild<QLineEdit*>(QStringLiteral("optionsRepeat"))->setText(kOptions);
            dialog.accept();
        }});
        action("protectAction")->trigger();
        EXPECT_EQ(driver.handled(), 1);
    }
    ASSERT_TRUE(document()->project().protection.has_value());
    action("saveAction")->trigger();
    const QByteArray saved = readFile(path);
    EXPECT_FALSE(saved.contains(kMain.toUtf8()));
    EXPECT_FALSE(saved.contains(kOptions.toUtf8()));
    EXPECT_EQ(rs::project::verifyProjectText(saved.toStdString()), std::nullopt);
    closeProject();

    // Read only: no edit of any kind, the undo stack stays empty, the text is locked.
    ASSERT_TRUE(openWith(path, "readOnly", {}));
    EXPECT_EQ(document()->permission(), Permission::ReadOnly);
    EXPECT_TRUE(window.windowTitle().contains(QStringLiteral("read only")));
    QSignalSpy refused(document(), &ProjectDocument::editRefused);
    EXPECT_FALSE(editText(document(), "option=\"on\"\nS(M0.5)", "option=\"off\"\nR(M0.5)"));
    EXPECT_FALSE(editText(document(), "Q0.3 = I0.1", "Q0.3 = I0.2"));
    EXPECT_EQ(refused.count(), 2);
    EXPECT_EQ(document()->undoStack()->count(), 0);
    EXPECT_FALSE(action("protectAction")->isEnabled());
    EXPECT_FALSE(action("markValidatedAction")->isEnabled());
    EXPECT_FALSE(action("newUnitAction")->isEnabled());
    // The project page says so, with the start of the key to compare.
    ASSERT_TRUE(window.showPage(rs::ui::PageRef::Kind::Project, 0));
    const QString protection = window.findChild<QLabel*>(QStringLiteral("protectionLabel"))->text();
    const QString key = QString::fromStdString(document()->project().protection->key);
    EXPECT_TRUE(protection.contains(key.left(4) + QLatin1Char(' ') + key.mid(4, 4)))
        << protection.toStdString();
    EXPECT_TRUE(protection.contains(QStringLiteral("opened read only")))
        << protection.toStdString();
    // No page offers an edit: its fields show, and stay as they are.
    EXPECT_TRUE(window.findChild<QLineEdit*>(QStringLiteral("projectNameEdit"))->isReadOnly());
    ASSERT_TRUE(window.showPage(rs::ui::PageRef::Kind::Unit, 0));
    EXPECT_FALSE(window.findChild<QComboBox*>(QStringLiteral("typeCombo"))->isEnabled());
    ASSERT_TRUE(window.showPage(rs::ui::PageRef::Kind::Variables, 0));
    EXPECT_EQ(window.findChild<rs::ui::VariablesPage*>()->table()->editTriggers(),
              QAbstractItemView::NoEditTriggers);
    ASSERT_TRUE(window.showPage(rs::ui::PageRef::Kind::IoOptions, 0));
    const auto boxes = window.findChild<rs::ui::IoOptionsPage*>()->findChildren<QComboBox*>();
    ASSERT_FALSE(boxes.isEmpty());
    EXPECT_FALSE(boxes.front()->isEnabled());
    ASSERT_TRUE(window.showUnit(0));
    EXPECT_TRUE(window.findChild<rs::ui::TextPage*>()->editor()->isReadOnly());
    closeProject();

    // Configure: the options' password opens the options, and nothing else;
    // the ladder offers no elements to place, and its option box still toggles.
    ASSERT_TRUE(openWith(path, "configure", kOptions));
    EXPECT_EQ(document()->permission(), Permission::Configure);
    showWindow();
    clickNode({rs::ui::PageRef::Kind::Ladder, document(), 0, 0});
    auto* ladder = window.findChild<rs::ui::LadderPage*>();
    EXPECT_FALSE(ladder->findChild<QToolBar*>(QStringLiteral("ladderToolBar"))->isVisible());
    ladder->toggleConfigOption(0, 0);
    EXPECT_TRUE(projectText().contains("option=\"off\"\nR(M0.5)")) << projectText().toStdString();
    EXPECT_FALSE(editText(document(), "Q0.3 = I0.1", "Q0.3 = I0.2"));
    action("saveAction")->trigger();
    EXPECT_TRUE(readFile(path).contains("option=\"off\"\nR(M0.5)"));
    EXPECT_EQ(rs::project::verifyProjectText(readFile(path).toStdString()), std::nullopt);
    closeProject();

    // Full permission takes the protection off.
    ASSERT_TRUE(openWith(path, "full", kMain));
    EXPECT_EQ(document()->permission(), Permission::Full);
    EXPECT_TRUE(editText(document(), "Q0.3 = I0.1", "Q0.3 = I0.2"));
    {
        DialogDriver driver({[](QDialog& dialog) {
            dialog.findChild<QCheckBox*>(QStringLiteral("protect"))->setChecked(false);
            dialog.accept();
        }});
        action("protectAction")->trigger();
    }
    action("saveAction")->trigger();
    EXPECT_FALSE(readFile(path).contains(";@protected"));
    EXPECT_TRUE(readFile(path).contains("Q0.3 = I0.2"));
}

TEST_F(PasswordProtectionTest, AWrongPasswordIsRefusedWithoutSayingWhichExistsAndWaits) {
    EXPECT_EQ(rs::project::waitAfterRefusal(1), 1);
    EXPECT_EQ(rs::project::waitAfterRefusal(3), 4);
    EXPECT_EQ(rs::project::waitAfterRefusal(9), 30);
    const QString path =
        writeFile(QStringLiteral("press.sps"), sealedPress(rs::project::OptionsAccess::Main));
    QString problem;
    bool okWaits = false;
    DialogDriver driver({[&](QDialog& dialog) {
        dialog.findChild<QLineEdit*>(QStringLiteral("password"))->setText(QStringLiteral("guess"));
        dialog.accept();
        EXPECT_TRUE(dialog.isVisible());
        problem = dialog.findChild<QLabel*>(QStringLiteral("problem"))->text();
        okWaits = !dialog.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->isEnabled();
        // A second try at once is not taken.
        dialog.findChild<QLineEdit*>(QStringLiteral("password"))->setText(kMain);
        dialog.accept();
        EXPECT_TRUE(dialog.isVisible());
        dialog.reject();
    }});
    EXPECT_FALSE(openFile(path));
    EXPECT_EQ(driver.handled(), 1);
    EXPECT_TRUE(problem.contains(QStringLiteral("does not open the project")))
        << problem.toStdString();
    EXPECT_FALSE(problem.contains(QStringLiteral("main")));
    EXPECT_TRUE(okWaits);
    EXPECT_TRUE(window.documents().empty());
}

TEST_F(PasswordProtectionTest, AFileEditedByHandIsReportedAtItsLineAndOpensReadOnly) {
    QByteArray text = sealedPress(rs::project::OptionsAccess::Free);
    text.replace("Q0.3 = I0.1", "Q0.3 = I0.7");
    const int line = 1 + static_cast<int>(text.left(text.indexOf("Q0.3 = I0.7")).count('\n'));
    const QString path = writeFile(QStringLiteral("press.sps"), text);
    MessageBoxAnswerer answerer(QMessageBox::Ok);
    ASSERT_TRUE(openFile(path));
    ASSERT_TRUE(answerer.answered());
    EXPECT_TRUE(answerer.text().contains(QStringLiteral("changed outside Rungsmith")));
    EXPECT_TRUE(answerer.informativeText().contains(QStringLiteral("line %1").arg(line)))
        << answerer.informativeText().toStdString();
    EXPECT_EQ(document()->permission(), Permission::ReadOnly);
    EXPECT_FALSE(editText(document(), "Q0.3 = I0.7", "Q0.3 = I0.1"));
    ASSERT_TRUE(window.showPage(rs::ui::PageRef::Kind::Project, 0));
    EXPECT_TRUE(window.findChild<QLabel*>(QStringLiteral("protectionLabel"))
                    ->text()
                    .contains(QStringLiteral("(first at line %1)").arg(line)));
}

} // namespace

namespace {

// The main password's holder can take a reviewed hand change as theirs: the
// project opens with full permission and saving seals it again.
TEST_F(PasswordProtectionTest, TheMainPasswordAcceptsAHandChange) {
    QByteArray text = sealedPress(rs::project::OptionsAccess::Main);
    text.replace("Q0.3 = I0.1", "Q0.3 = I0.1 * I0.4");
    const QString path = writeFile(QStringLiteral("press.sps"), text);
    bool onlyFull = false;
    DialogDriver driver(
        {[](QDialog& dialog) {
             auto& box = static_cast<QMessageBox&>(dialog);
             box.button(QMessageBox::Yes)->click();
         },
         [&](QDialog& dialog) {
             onlyFull = !dialog.findChild<QRadioButton*>(QStringLiteral("readOnly"))->isEnabled();
             dialog.findChild<QLineEdit*>(QStringLiteral("password"))->setText(kMain);
             dialog.accept();
         }});
    ASSERT_TRUE(openFile(path));
    EXPECT_EQ(driver.handled(), 2);
    EXPECT_TRUE(onlyFull);
    EXPECT_EQ(document()->permission(), Permission::Full);
    EXPECT_FALSE(document()->tampering().has_value());
    action("saveAction")->trigger();
    EXPECT_EQ(rs::project::verifyProjectText(readFile(path).toStdString()), std::nullopt);
    EXPECT_TRUE(readFile(path).contains("Q0.3 = I0.1 * I0.4"));
}

} // namespace
