// SPDX-License-Identifier: GPL-3.0-or-later
#include "WindowTest.h"

#include "DialogDriver.h"
#include "FormInput.h"
#include "MessageBoxAnswerer.h"
#include "document/ProjectDocument.h"
#include "pages/CsvExportDialog.h"
#include "pages/CsvImportDialog.h"
#include "pages/IoOptionsPage.h"
#include "pages/RemanentDialog.h"
#include "pages/UnitPage.h"
#include "pages/VariableTableModel.h"
#include "pages/VariablesPage.h"
#include "pl110/Pl110Document.h"
#include "pl110/Pl110Window.h"
#include "shell/ProjectTree.h"
#include "text/ProgramEditor.h"
#include "text/TextPage.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSortFilterProxyModel>
#include <QTabBar>
#include <QTableView>
#include <QTest>
#include <QTreeWidget>

#include "QtPrinting.h"

#include <gtest/gtest.h>

namespace {

using rs::ui::MainWindow;
using rs::ui::PageRef;

void typeInto(QLineEdit* edit, const QString& text) {
    edit->setFocus();
    edit->selectAll();
    QTest::keyClicks(edit, text);
}

class ProjectWorkflowTest : public WindowTest {
protected:
    // File > New, answered as the manual's tutorial does: a project, then its first unit.
    void createProjectWithUnit() {
        DialogDriver driver({
            [](QDialog& dialog) {
                typeInto(child<QLineEdit>(dialog, QStringLiteral("projectNameEdit")),
                         QStringLiteral("Press line"));
                auto* description =
                    child<QPlainTextEdit>(dialog, QStringLiteral("projectDescriptionEdit"));
                description->setFocus();
                QTest::keyClicks(description, QStringLiteral("Two presses"));
                QTest::mouseClick(child<QCheckBox>(dialog, QStringLiteral("includeSourceCheck")),
                                  Qt::LeftButton);
                clickOk(dialog);
            },
            [](QDialog& dialog) {
                choose(child<QComboBox>(dialog, QStringLiteral("typeCombo")),
                       QStringLiteral("B46"));
                choose(child<QComboBox>(dialog, QStringLiteral("stationCombo")),
                       QStringLiteral("3"));
                QTest::mouseClick(child<QRadioButton>(dialog, QStringLiteral("instructionSet3")),
                                  Qt::LeftButton);
                choose(child<QComboBox>(dialog, QStringLiteral("idfixKindCombo")),
                       QStringLiteral("IDFIX number"));
                auto* idfix = child<QLineEdit>(dialog, QStringLiteral("idfixEdit"));
                typeInto(idfix, QStringLiteral("0000abcd12"));
                // Ten digits are not an IDFIX yet: OK waits for all twelve.
                auto* buttons = dialog.findChild<QDialogButtonBox*>();
                EXPECT_FALSE(buttons->button(QDialogButtonBox::Ok)->isEnabled());
                QTest::keyClicks(idfix, QStringLiteral("34zz")); // letters past F are refused
                typeInto(child<QLineEdit>(dialog, QStringLiteral("unitDescriptionEdit")),
                         QStringLiteral("Cabinet A"));
                clickOk(dialog);
            },
        });
        action("newAction")->trigger();
        ASSERT_TRUE(driver.done());
        activate(); // the dialogs had the keyboard
    }

    QTableView* variableTable() { return window.variablesPage()->table(); }

    QModelIndex variableCell(const QString& address, int column) {
        QAbstractItemModel* model = variableTable()->model();
        for (int row = 0; row < model->rowCount(); ++row) {
            const QModelIndex index = model->index(row, column);
            if (index.data(rs::ui::VariableTableModel::kAddressRole).toString() == address)
                return index;
        }
        ADD_FAILURE() << "no row " << address.toStdString();
        return {};
    }

    // Edits a cell the way a user does: select it, F2, type, Enter.
    void editCell(const QString& address, int column, const QString& text) {
        // The editor of the last edit is gone first, so that only this one is found.
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
        const QModelIndex index = variableCell(address, column);
        variableTable()->setFocus();
        variableTable()->setCurrentIndex(index);
        QTest::keyClick(variableTable(), Qt::Key_F2);
        QLineEdit* editor = nullptr;
        for (auto* edit : variableTable()->viewport()->findChildren<QLineEdit*>())
            if (edit->isVisible())
                editor = edit;
        ASSERT_NE(editor, nullptr);
        editor->selectAll();
        QTest::keyClicks(editor, text);
        QTest::keyClick(editor, Qt::Key_Return);
        // The delegate commits what was typed in a queued call.
        QCoreApplication::sendPostedEvents();
    }

    void showTab(const QString& name) {
        QTabBar* tabs = window.variablesPage()->tabs();
        for (int i = 0; i < tabs->count(); ++i)
            if (tabs->tabText(i) == name) {
                tabs->setCurrentIndex(i);
                return;
            }
        ADD_FAILURE() << "no tab " << name.toStdString();
    }

    void undo() { action("undoAction")->trigger(); }
    void redo() { action("redoAction")->trigger(); }
};

TEST_F(ProjectWorkflowTest, NewProjectAndUnitFromTheDialogs) {
    showWindow();
    createProjectWithUnit();
    ASSERT_EQ(window.documents().size(), 1u);
    EXPECT_EQ(window.currentPage().kind, PageRef::Kind::Unit);
    EXPECT_EQ(window.currentPage().station, 3);
    QTreeWidgetItem* unit = window.projectTree()->itemFor({PageRef::Kind::Unit, document(), 3});
    ASSERT_NE(unit, nullptr);
    EXPECT_EQ(unit->text(0), QStringLiteral("Pluto 3 — B46"));
    EXPECT_EQ(projectText(), "$name Press line\n"
                             ";@project description=\"Two presses\" include_source=\"yes\"\n"
                             "\n"
                             "! id_pluto_Double:03=0000ABCD1234\n"
                             ";@unit 03 description=\"Cabinet A\"\n"
                             "! type_pluto:03=B46,is3\n"
                             "\n"
                             "! pgm_pluto:03\n"
                             "\n"
                             "S3.0_0\n");
    EXPECT_TRUE(window.isWindowModified());
    // One undo step takes the unit away again, and the tree follows.
    undo();
    EXPECT_EQ(window.projectTree()->itemFor({PageRef::Kind::Unit, document(), 3}), nullptr);
    redo();
    EXPECT_NE(window.projectTree()->itemFor({PageRef::Kind::Unit, document(), 3}), nullptr);
}

TEST_F(ProjectWorkflowTest, NewProjectForAPl110OpensItsWindowOnARunnableProgram) {
    const int projectsBefore =
        static_cast<int>(window.findChildren<rs::ui::ProjectDocument*>().size());
    DialogDriver driver({[](QDialog& dialog) {
        choose(child<QComboBox>(dialog, QStringLiteral("projectTargetCombo")),
               QStringLiteral("Pixsys PL110 (one ladder PLC)"));
        // The Pluto-only fields do not apply.
        EXPECT_FALSE(child<QCheckBox>(dialog, QStringLiteral("includeSourceCheck"))->isEnabled());
        typeInto(child<QLineEdit>(dialog, QStringLiteral("projectNameEdit")),
                 QStringLiteral("Mixer"));
        clickOk(dialog);
    }});
    action("newAction")->trigger();
    ASSERT_TRUE(driver.done());
    rs::ui::Pl110Window* opened = nullptr;
    for (QWidget* widget : QApplication::topLevelWidgets())
        if (auto* pl110 = qobject_cast<rs::ui::Pl110Window*>(widget))
            opened = pl110;
    ASSERT_NE(opened, nullptr);
    EXPECT_TRUE(opened->document()->text().contains("$name Mixer"));
    EXPECT_TRUE(opened->document()->isRunnable());
    EXPECT_EQ(static_cast<int>(window.findChildren<rs::ui::ProjectDocument*>().size()),
              projectsBefore); // no Pluto project was made
    opened->document()->undoStack()->setClean();
    opened->close();
}

TEST_F(ProjectWorkflowTest, IoOptionsOfferOnlyLegalChoicesAndUndo) {
    showWindow();
    createProjectWithUnit();
    clickNode({PageRef::Kind::IoOptions, document(), 3});
    ASSERT_EQ(window.currentPage().kind, PageRef::Kind::IoOptions);
    rs::ui::IoOptionsPage& page = *window.ioOptionsPage();
    auto* type = child<QComboBox>(page, QStringLiteral("signalType:I3.0"));
    auto* shape = child<QComboBox>(page, QStringLiteral("signalShape:I3.0"));
    auto* nonInverted = child<QCheckBox>(page, QStringLiteral("nonInverted:I3.0"));
    // An input terminal is an input or undefined; a light button is not on its list.
    EXPECT_EQ(type->count(), 2);
    EXPECT_FALSE(shape->isEnabled());

    choose(type, QStringLiteral("Input"));
    EXPECT_TRUE(projectText().contains("! I3.0,static\n"));
    EXPECT_FALSE(nonInverted->isEnabled()); // Non_Inv is for dynamic signals
    choose(shape, QStringLiteral("A_Pulse"));
    EXPECT_TRUE(nonInverted->isEnabled());
    QTest::mouseClick(nonInverted, Qt::LeftButton);
    EXPECT_TRUE(projectText().contains("! I3.0,a_pulse,non_inv\n"));
    // Back to static: the option that static cannot have goes with it.
    choose(shape, QStringLiteral("Static"));
    EXPECT_TRUE(projectText().contains("! I3.0,static\n"));
    EXPECT_FALSE(nonInverted->isChecked());

    // A configurable terminal can be a light button, with the dynamic shapes only.
    auto* iqType = child<QComboBox>(page, QStringLiteral("signalType:IQ3.12"));
    choose(iqType, QStringLiteral("Light button"));
    auto* iqShape = child<QComboBox>(page, QStringLiteral("signalShape:IQ3.12"));
    EXPECT_EQ(iqShape->findText(QStringLiteral("Static")), -1);
    EXPECT_TRUE(projectText().contains("! IQ3.12,a_pulse\n"));

    undo();
    EXPECT_FALSE(projectText().contains("IQ3.12"));
    undo();
    EXPECT_TRUE(projectText().contains("! I3.0,a_pulse,non_inv\n"));
    EXPECT_TRUE(nonInverted->isChecked()); // the page follows the project
    EXPECT_EQ(shape->currentText(), QStringLiteral("A_Pulse"));
    undo();
    undo();
    undo();
    EXPECT_FALSE(projectText().contains("I3.0,"));
    EXPECT_EQ(type->currentText(), QStringLiteral("Undefined"));
    for (int i = 0; i < 5; ++i)
        redo();
    EXPECT_TRUE(projectText().contains("! I3.0,static\n! IQ3.12,a_pulse\n"));
}

// Issue 17, finding 7: Return on a refused name keeps what was typed, to mend.
TEST_F(ProjectWorkflowTest, ARefusedNameStaysInItsEditorToBeMended) {
    showWindow();
    createProjectWithUnit();
    clickNode({PageRef::Kind::Variables, document(), 3});
    const QByteArray before = projectText();
    editCell(QStringLiteral("I3.0"), rs::ui::VariableTableModel::NameColumn,
             QStringLiteral("1Start"));
    QLineEdit* editor = nullptr;
    for (auto* edit : variableTable()->viewport()->findChildren<QLineEdit*>())
        if (edit->isVisible())
            editor = edit;
    ASSERT_NE(editor, nullptr) << "the editor closed and the name was lost";
    EXPECT_EQ(editor->text(), QStringLiteral("1Start"));
    EXPECT_TRUE(window.variablesPage()->message().contains(QStringLiteral("digit")));
    EXPECT_EQ(projectText(), before);
    // Mended in place: the digit goes, and Return takes the name.
    editor->setCursorPosition(1);
    QTest::keyClick(editor, Qt::Key_Backspace);
    QTest::keyClick(editor, Qt::Key_Return);
    QCoreApplication::sendPostedEvents();
    EXPECT_TRUE(projectText().contains("! I3.0=Start\n")) << projectText().toStdString();
}

TEST_F(ProjectWorkflowTest, VariablesAreNamedAndDescribedInTheTable) {
    showWindow();
    createProjectWithUnit();
    clickNode({PageRef::Kind::Variables, document(), 3});
    rs::ui::VariablesPage& page = *window.variablesPage();
    QStringList tabs;
    for (int i = 0; i < page.tabs()->count(); ++i)
        tabs << page.tabs()->tabText(i);
    EXPECT_EQ(tabs, (QStringList{"Safety Inputs", "Safety Outputs", "NonSafety Outputs",
                                 "Global Memories", "Memories", "Registers", "Double Registers",
                                 "System Memories", "System Registers"}));
    const QByteArray before = projectText();

    // A name the manual's rules refuse is reported as it is typed and not taken.
    editCell(QStringLiteral("I3.0"), rs::ui::VariableTableModel::NameColumn, QStringLiteral("1st"));
    EXPECT_TRUE(page.message().contains(QStringLiteral("digit"))) << page.message().toStdString();
    EXPECT_EQ(projectText(), before);

    editCell(QStringLiteral("I3.0"), rs::ui::VariableTableModel::NameColumn,
             QStringLiteral("EStop"));
    EXPECT_TRUE(projectText().contains("! I3.0=EStop\n"));
    editCell(QStringLiteral("I3.0"), rs::ui::VariableTableModel::DescriptionColumn,
             QStringLiteral("Emergency stop, NC"));
    EXPECT_TRUE(projectText().contains(";@var I3.0 description=\"Emergency stop, NC\"\n"));
    EXPECT_EQ(variableCell(QStringLiteral("I3.0"), rs::ui::VariableTableModel::AttributesColumn)
                  .data()
                  .toString(),
              QStringLiteral("[G]"));

    // The same name for another variable of the unit is refused with the reason.
    editCell(QStringLiteral("I3.1"), rs::ui::VariableTableModel::NameColumn,
             QStringLiteral("estop"));
    EXPECT_TRUE(page.message().contains(QStringLiteral("I3.0"))) << page.message().toStdString();
    EXPECT_FALSE(projectText().contains("I3.1="));

    // The filter keeps the rows that match.
    auto* filter = child<QLineEdit>(page, QStringLiteral("variableFilter"));
    typeInto(filter, QStringLiteral("emergency"));
    EXPECT_EQ(variableTable()->model()->rowCount(), 1);
    filter->clear();

    undo();
    EXPECT_FALSE(projectText().contains("description=\"Emergency"));
    undo();
    EXPECT_EQ(projectText(), before);
    EXPECT_EQ(variableCell(QStringLiteral("I3.0"), rs::ui::VariableTableModel::NameColumn).data(),
              QString());
    redo();
    redo();
    EXPECT_TRUE(projectText().contains("! I3.0=EStop\n"));
}

TEST_F(ProjectWorkflowTest, ExportVariablesStayWithinTheTelegramLimits) {
    showWindow();
    createProjectWithUnit();
    clickNode({PageRef::Kind::Variables, document(), 3});
    rs::ui::VariablesPage& page = *window.variablesPage();
    showTab(QStringLiteral("Double Registers"));
    for (int i = 0; i < 4; ++i)
        EXPECT_TRUE(
            page.setExported({rs::lang::AddressKind::DoubleRegister, 3, i * 2}, true).isEmpty());
    EXPECT_TRUE(projectText().contains(";@var DR3.6 export=\"yes\"\n"));
    EXPECT_TRUE(child<QLabel>(page, QStringLiteral("variableExportPairs"))
                    ->text()
                    .contains(QStringLiteral("4 of 4")));
    const QString refusal = page.setExported({rs::lang::AddressKind::Memory, 3, 0}, true);
    EXPECT_FALSE(refusal.isEmpty());
    EXPECT_EQ(page.message(), refusal);
    EXPECT_FALSE(projectText().contains("M3.0"));
    EXPECT_EQ(variableCell(QStringLiteral("DR3.6"), rs::ui::VariableTableModel::AttributesColumn)
                  .data()
                  .toString(),
              QStringLiteral("[E]"));
    // A global variable is seen by the other units already.
    EXPECT_FALSE(page.setExported({rs::lang::AddressKind::Input, 3, 0}, true).isEmpty());
    undo();
    EXPECT_FALSE(projectText().contains("DR3.6"));
}

TEST_F(ProjectWorkflowTest, RemanentVariablesFollowTheManualsRule) {
    showWindow();
    createProjectWithUnit();
    clickNode({PageRef::Kind::Variables, document(), 3});
    {
        DialogDriver driver({[](QDialog& dialog) {
            auto& remanent = static_cast<rs::ui::RemanentDialog&>(dialog);
            QTest::mouseClick(remanent.box(rs::lang::AddressKind::Register, 100), Qt::LeftButton);
            QTest::mouseClick(remanent.box(rs::lang::AddressKind::Memory, 101), Qt::LeftButton);
            clickOk(dialog);
        }});
        action("remanentAction")->trigger();
        ASSERT_TRUE(driver.done());
    }
    EXPECT_TRUE(
        projectText().contains(";@unit 03 description=\"Cabinet A\" remanent=\"M101,R100\"\n"));
    showTab(QStringLiteral("Memories"));
    EXPECT_EQ(variableCell(QStringLiteral("M3.101"), rs::ui::VariableTableModel::AttributesColumn)
                  .data()
                  .toString(),
              QStringLiteral("[R]"));
    {
        DialogDriver driver({[](QDialog& dialog) {
            auto& remanent = static_cast<rs::ui::RemanentDialog&>(dialog);
            for (int i = 100; i <= 131; ++i)
                if (!remanent.box(rs::lang::AddressKind::Register, i)->isChecked())
                    QTest::mouseClick(remanent.box(rs::lang::AddressKind::Register, i),
                                      Qt::LeftButton);
            // Every register: no memory can be remanent any more.
            EXPECT_FALSE(remanent.box(rs::lang::AddressKind::Memory, 101)->isEnabled());
            EXPECT_FALSE(remanent.box(rs::lang::AddressKind::Memory, 101)->isChecked());
            clickOk(dialog);
        }});
        action("remanentAction")->trigger();
        ASSERT_TRUE(driver.done());
    }
    EXPECT_TRUE(projectText().contains("remanent=\"R100-R131\"\n"));
    undo();
    EXPECT_TRUE(projectText().contains("remanent=\"M101,R100\"\n"));
}

TEST_F(ProjectWorkflowTest, CsvExportAndImportWithPreviewAndUndo) {
    showWindow();
    createProjectWithUnit();
    clickNode({PageRef::Kind::Variables, document(), 3});
    editCell(QStringLiteral("I3.0"), rs::ui::VariableTableModel::NameColumn,
             QStringLiteral("EStop"));
    editCell(QStringLiteral("I3.0"), rs::ui::VariableTableModel::DescriptionColumn,
             QStringLiteral("Stop; NC"));

    const QString exported = directory.filePath(QStringLiteral("names.csv"));
    {
        DialogDriver driver({[&](QDialog& dialog) {
            typeInto(child<QLineEdit>(dialog, QStringLiteral("csvPathEdit")), exported);
            choose(child<QComboBox>(dialog, QStringLiteral("csvSeparatorCombo")),
                   QStringLiteral("Semicolon (;)"));
            auto* buttons = dialog.findChild<QDialogButtonBox*>();
            for (QAbstractButton* button : buttons->buttons())
                if (buttons->buttonRole(button) == QDialogButtonBox::AcceptRole)
                    QTest::mouseClick(button, Qt::LeftButton);
        }});
        action("exportCsvAction")->trigger();
        ASSERT_TRUE(driver.done());
    }
    EXPECT_EQ(readFile(exported), "\xEF\xBB\xBFVariable;Symbolic Name;Description\r\n"
                                  "I3.0;EStop;\"Stop; NC\"\r\n");

    // The spreadsheet's edit: a new name, a rename, and two bad rows.
    const QString edited =
        writeFile(QStringLiteral("edited.csv"), "\xEF\xBB\xBFVariable;Symbolic Name;Description\r\n"
                                                "I3.0;EmergencyStop;\"Stop; NC\"\r\n"
                                                "I3.1;Reset;Reset button\r\n"
                                                "I3.99;Nowhere;\r\n"
                                                "M3.2;2bad;\r\n");
    const QByteArray before = projectText();
    auto importDriver = [&](bool confirm) {
        return DialogDriver({[&, confirm](QDialog& dialog) {
            auto& import = static_cast<rs::ui::CsvImportDialog&>(dialog);
            import.setPath(edited);
            EXPECT_EQ(import.changesView()->topLevelItemCount(), 2);
            ASSERT_EQ(import.problemsView()->topLevelItemCount(), 2);
            EXPECT_EQ(import.problemsView()->topLevelItem(0)->text(0), QStringLiteral("4"));
            EXPECT_EQ(import.problemsView()->topLevelItem(1)->text(0), QStringLiteral("5"));
            EXPECT_EQ(import.changesView()->topLevelItem(0)->text(2),
                      QStringLiteral("EStop → EmergencyStop"));
            if (confirm)
                QTest::mouseClick(child<QPushButton>(dialog, QStringLiteral("csvImportButton")),
                                  Qt::LeftButton);
            else
                dialog.reject();
        }});
    };
    {
        DialogDriver driver = importDriver(false);
        action("importCsvAction")->trigger();
        ASSERT_TRUE(driver.done());
    }
    EXPECT_EQ(projectText(), before); // nothing changes without Import
    {
        DialogDriver driver = importDriver(true);
        action("importCsvAction")->trigger();
        ASSERT_TRUE(driver.done());
    }
    EXPECT_TRUE(projectText().contains("! I3.0=EmergencyStop\n"));
    EXPECT_TRUE(projectText().contains("! I3.1=Reset\n"));
    EXPECT_TRUE(projectText().contains(";@var I3.1 description=\"Reset button\"\n"));
    undo(); // the whole import is one step
    EXPECT_EQ(projectText(), before);
    redo();
    EXPECT_TRUE(projectText().contains("! I3.1=Reset\n"));
}

TEST_F(ProjectWorkflowTest, TheCodeIsEditedAsTextAndEveryPageFollows) {
    showWindow();
    createProjectWithUnit();
    clickNode({PageRef::Kind::Variables, document(), 3});
    editCell(QStringLiteral("I3.0"), rs::ui::VariableTableModel::NameColumn,
             QStringLiteral("EStop"));

    clickNode({PageRef::Kind::Ladder, document(), 3, 0});
    action("codeViewAction")->trigger(); // the code's text
    rs::ui::ProgramEditor* editor = window.editor();
    EXPECT_TRUE(editor->textBytes().startsWith("! pgm_pluto:03\n"));
    editor->setFocus();
    QTest::keyClick(editor, Qt::Key_End, Qt::ControlModifier);
    QTest::keyClick(editor, Qt::Key_Return);
    QTest::keyClicks(editor, QStringLiteral("q3.4 = estop"));
    ASSERT_TRUE(QTest::qWaitFor([&] { return projectText().contains("Q3.4 = EStop\n"); },
                                MainWindow::kCheckDelayMs * 5));
    // The variables page shows the input in use now.
    clickNode({PageRef::Kind::Variables, document(), 3});
    EXPECT_FALSE(variableCell(QStringLiteral("I3.0"), rs::ui::VariableTableModel::StatusColumn)
                     .data(Qt::DisplayRole)
                     .isNull());
    // A rename on the variables page shows in the code.
    editCell(QStringLiteral("I3.0"), rs::ui::VariableTableModel::NameColumn,
             QStringLiteral("Stop"));
    clickNode({PageRef::Kind::Ladder, document(), 3, 0});
    action("codeViewAction")->trigger(); // the code's text
    EXPECT_TRUE(editor->textBytes().contains("Q3.4 = Stop\n")) << editor->textBytes().toStdString();

    // Ctrl+Z in the editor is the project's undo: the rename, then the typing.
    editor->setFocus();
    QTest::keyClick(editor, Qt::Key_Z, Qt::ControlModifier);
    EXPECT_TRUE(editor->textBytes().contains("Q3.4 = EStop\n"))
        << editor->textBytes().toStdString();
    QTest::keyClick(editor, Qt::Key_Z, Qt::ControlModifier);
    EXPECT_FALSE(projectText().contains("Q3.4"));
    EXPECT_FALSE(editor->textBytes().contains("Q3.4"));
    QTest::keyClick(editor, Qt::Key_Y, Qt::ControlModifier);
    EXPECT_TRUE(projectText().contains("Q3.4 = EStop\n"));
}

TEST_F(ProjectWorkflowTest, TheUnitPageChangesTheTypeAfterSayingWhatGoes) {
    showWindow();
    createProjectWithUnit();
    clickNode({PageRef::Kind::Variables, document(), 3});
    showTab(QStringLiteral("Safety Outputs"));
    editCell(QStringLiteral("Q3.4"), rs::ui::VariableTableModel::NameColumn,
             QStringLiteral("Valve"));
    clickNode({PageRef::Kind::Unit, document(), 3});
    auto* type = child<QComboBox>(*window.unitPage(), QStringLiteral("typeCombo"));
    const QByteArray before = projectText();
    {
        MessageBoxAnswerer no(QMessageBox::No);
        choose(type, QStringLiteral("A20")); // an A20 has no Q3.4
        EXPECT_TRUE(no.answered());
        EXPECT_TRUE(no.text().contains(QStringLiteral("removes 1 name")))
            << no.text().toStdString();
    }
    EXPECT_EQ(projectText(), before);
    EXPECT_EQ(type->currentText(), QStringLiteral("B46"));
    {
        MessageBoxAnswerer yes(QMessageBox::Yes);
        choose(type, QStringLiteral("A20"));
        EXPECT_TRUE(yes.answered());
    }
    EXPECT_TRUE(projectText().contains("! id_pluto:03=0000ABCD1234\n"));
    EXPECT_FALSE(projectText().contains("Valve"));
    EXPECT_EQ(window.projectTree()->itemFor({PageRef::Kind::Unit, document(), 3})->text(0),
              QStringLiteral("Pluto 3 — A20"));
    undo();
    EXPECT_EQ(projectText(), before);
}

TEST_F(ProjectWorkflowTest, SaveReopenCompare) {
    showWindow();
    createProjectWithUnit();
    clickNode({PageRef::Kind::IoOptions, document(), 3});
    choose(child<QComboBox>(*window.ioOptionsPage(), QStringLiteral("signalType:I3.1")),
           QStringLiteral("Input"));
    clickNode({PageRef::Kind::Variables, document(), 3});
    editCell(QStringLiteral("I3.1"), rs::ui::VariableTableModel::NameColumn,
             QStringLiteral("Start"));
    window.variablesPage()->setExported({rs::lang::AddressKind::Memory, 3, 7}, true);

    const QString path = directory.filePath(QStringLiteral("press.sps"));
    ASSERT_TRUE(window.saveDocumentAs(document(), path));
    EXPECT_FALSE(window.isWindowModified());
    const QByteArray saved = readFile(path);
    EXPECT_EQ(saved, projectText());

    MainWindow reopened;
    ASSERT_TRUE(reopened.loadFile(path).isEmpty());
    rs::ui::ProjectDocument* again = reopened.currentDocument();
    EXPECT_TRUE(again->project() == document()->project());
    EXPECT_FALSE(again->isModified());
    ASSERT_TRUE(reopened.saveDocument(again));
    EXPECT_EQ(readFile(path), saved);
}

} // namespace
