// SPDX-License-Identifier: GPL-3.0-or-later
// The manual's tutorial (Part 1, 3.1-3.13) done as a user does it: a new
// project and unit, the variables named, the muting network and the reset
// network made of library blocks and the rest drawn by key, saved, reopened,
// compiled, and the saved file run against a scenario of what the tutorial's
// program does.
#include "WindowTest.h"

#include "DialogDriver.h"
#include "FormInput.h"
#include "ProgramRun.h"
#include "document/ProjectDocument.h"
#include "ladder/LadderPage.h"
#include "ladder/LadderView.h"
#include "ladder/NetworkItem.h"
#include "output/CompileOutput.h"
#include "pages/VariableTableModel.h"
#include "pages/VariablesPage.h"

#include <QAction>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QRadioButton>
#include <QTabBar>
#include <QTableView>
#include <QTest>

#include "QtPrinting.h"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

namespace {

using rs::ui::LadderPage;
using rs::ui::PageRef;
using rs::ui::VariableTableModel;

// Pin name and what is typed into its field.
using PinEntries = std::vector<std::pair<QString, QString>>;

void typeIntoField(QDialog& dialog, const QString& name, const QString& text) {
    auto* field = dialog.findChild<QLineEdit*>(name);
    ASSERT_NE(field, nullptr) << name.toStdString();
    field->setFocus();
    field->selectAll();
    QTest::keyClick(field, Qt::Key_Backspace);
    QTest::keyClicks(field, text);
}

void chooseInDialog(QDialog& dialog, const QString& combo, const QString& text) {
    auto* box = dialog.findChild<QComboBox*>(combo);
    ASSERT_NE(box, nullptr) << combo.toStdString();
    const int index = box->findText(text);
    ASSERT_GE(index, 0) << text.toStdString();
    box->setCurrentIndex(index);
}

class TutorialTest : public WindowTest {
protected:
    LadderPage& page() { return *window.ladderPage(); }

    // File > New (3.1-3.6): the project, then its Pluto A20 with instruction set 3.
    void newProject() {
        DialogDriver driver({
            [](QDialog& dialog) {
                typeIntoField(dialog, QStringLiteral("projectNameEdit"),
                              QStringLiteral("Muting tutorial"));
                clickOk(dialog);
            },
            [](QDialog& dialog) {
                chooseInDialog(dialog, QStringLiteral("typeCombo"), QStringLiteral("A20"));
                chooseInDialog(dialog, QStringLiteral("stationCombo"), QStringLiteral("0"));
                QTest::mouseClick(
                    dialog.findChild<QRadioButton*>(QStringLiteral("instructionSet3")),
                    Qt::LeftButton);
                chooseInDialog(dialog, QStringLiteral("idfixKindCombo"),
                               QStringLiteral("IDFIX number"));
                typeIntoField(dialog, QStringLiteral("idfixEdit"), QStringLiteral("000034AD4AE1"));
                clickOk(dialog);
            },
        });
        action("newAction")->trigger();
        ASSERT_TRUE(driver.done());
        activate(); // the dialogs had the keyboard
    }

    // A cell of the Variables page edited as a user does: select, F2, type, Enter.
    void editVariable(const QString& tab, const QString& address, int column, const QString& text) {
        rs::ui::VariablesPage& variables = *window.variablesPage();
        QTabBar* tabs = variables.tabs();
        for (int i = 0; i < tabs->count(); ++i)
            if (tabs->tabText(i) == tab)
                tabs->setCurrentIndex(i);
        ASSERT_EQ(tabs->tabText(tabs->currentIndex()), tab);
        // The editor of the last edit is gone first, so that only this one is found.
        QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
        QTableView* table = variables.table();
        QModelIndex cell;
        for (int row = 0; row < table->model()->rowCount(); ++row) {
            const QModelIndex index = table->model()->index(row, column);
            if (index.data(VariableTableModel::kAddressRole).toString() == address)
                cell = index;
        }
        ASSERT_TRUE(cell.isValid()) << address.toStdString();
        table->setFocus();
        table->setCurrentIndex(cell);
        QTest::keyClick(table, Qt::Key_F2);
        QLineEdit* editor = nullptr;
        for (auto* edit : table->viewport()->findChildren<QLineEdit*>())
            if (edit->isVisible())
                editor = edit;
        ASSERT_NE(editor, nullptr);
        editor->selectAll();
        QTest::keyClicks(editor, text);
        QTest::keyClick(editor, Qt::Key_Return);
        QCoreApplication::sendPostedEvents(); // the delegate commits in a queued call
        EXPECT_TRUE(variables.message().isEmpty()) << variables.message().toStdString();
    }

    void name(const QString& tab, const QString& address, const QString& symbol,
              const QString& description = {}) {
        editVariable(tab, address, VariableTableModel::NameColumn, symbol);
        if (!description.isEmpty())
            editVariable(tab, address, VariableTableModel::DescriptionColumn, description);
    }

    // The key of an element, its properties dialog filled in and closed by Enter.
    void insert(char key, const QString& operand) {
        DialogDriver driver({[&](QDialog& dialog) {
            typeIntoField(dialog, QStringLiteral("operand"), operand);
            QTest::keyClick(dialog.findChild<QLineEdit*>(QStringLiteral("operand")),
                            Qt::Key_Return);
        }});
        QTest::keyClick(page().view(), key);
        ASSERT_TRUE(driver.done()) << "no dialog for " << key;
        EXPECT_TRUE(page().message().isEmpty()) << page().message().toStdString();
    }

    // As insert, naming the memory on the way with the dialog's New Variable... (3.10).
    void insertNamingNew(char key, const QString& address, const QString& symbol) {
        DialogDriver driver({[&](QDialog& dialog) {
            typeIntoField(dialog, QStringLiteral("operand"), address);
            // A driver's timer does not fire again inside its own handler, so
            // the dialog this one opens needs a driver of its own.
            DialogDriver naming({[&](QDialog& newVariable) {
                typeIntoField(newVariable, QStringLiteral("name"), symbol);
                clickOk(newVariable);
            }});
            QTest::mouseClick(dialog.findChild<QPushButton*>(QStringLiteral("newVariable")),
                              Qt::LeftButton);
            ASSERT_TRUE(naming.done());
            QTest::keyClick(dialog.findChild<QLineEdit*>(QStringLiteral("operand")),
                            Qt::Key_Return);
        }});
        QTest::keyClick(page().view(), key);
        ASSERT_TRUE(driver.done()) << "no dialog for " << key;
        EXPECT_TRUE(page().message().isEmpty()) << page().message().toStdString();
    }

    // Function... (Shift+F): the block found by typing in the chooser's filter,
    // then its pins typed into the pins dialog.
    void insertBlock(const QString& filter, const QString& block, const PinEntries& pins) {
        DialogDriver driver(
            {[&](QDialog& chooser) {
                 typeIntoField(chooser, QStringLiteral("filter"), filter);
                 auto* list = chooser.findChild<QListWidget*>(QStringLiteral("blocks"));
                 ASSERT_NE(list, nullptr);
                 ASSERT_EQ(list->count(), 1) << filter.toStdString();
                 EXPECT_TRUE(list->currentItem()->text().startsWith(block));
                 QTest::keyClick(chooser.findChild<QLineEdit*>(QStringLiteral("filter")),
                                 Qt::Key_Return);
             },
             [&](QDialog& dialog) {
                 for (const auto& pin : pins)
                     typeIntoField(dialog, QStringLiteral("pin_") + pin.first, pin.second);
                 clickOk(dialog);
             }});
        QTest::keyClick(page().view(), Qt::Key_F, Qt::ShiftModifier);
        ASSERT_TRUE(driver.done()) << block.toStdString();
        EXPECT_TRUE(page().message().isEmpty()) << page().message().toStdString();
    }

    // File > Save of a project never saved asks for its file (3.4): the
    // folder chosen, the name typed, Enter.
    void saveAs(const QString& path) {
        DialogDriver driver({[&](QDialog& dialog) {
            auto& files = static_cast<QFileDialog&>(dialog);
            files.setDirectory(QFileInfo(path).path());
            auto* fileName = files.findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
            ASSERT_NE(fileName, nullptr);
            fileName->setFocus();
            QTest::keyClicks(fileName, QFileInfo(path).fileName());
            QTest::keyClick(fileName, Qt::Key_Return);
        }});
        action("saveAction")->trigger();
        ASSERT_TRUE(driver.done());
    }

    bool waitForCompile() {
        return QTest::qWaitFor([&] { return !window.isCompiling(); }, 30000);
    }
};

TEST_F(TutorialTest, TheMutingApplicationIsDrawnSavedReopenedCompiledAndBehaves) {
    showWindow();
    newProject();
    ASSERT_NE(document(), nullptr);

    // 3.9: the Variables page, with the names of the manual's text example
    // (Part 2, 5.4) for the muting memory and the reset indicator.
    clickNode({PageRef::Kind::Variables, document(), 0});
    const QString inputs = QStringLiteral("Safety Inputs");
    name(inputs, QStringLiteral("I0.0"), QStringLiteral("MuteSensor1"),
         QStringLiteral("Sensor for initiation of muting"));
    name(inputs, QStringLiteral("I0.1"), QStringLiteral("MuteSensor2"),
         QStringLiteral("Sensor for initiation of muting"));
    name(inputs, QStringLiteral("I0.2"), QStringLiteral("ContMonitor"),
         QStringLiteral("NC contacts of contactors for monitoring"));
    name(inputs, QStringLiteral("I0.12"), QStringLiteral("EStopButton"),
         QStringLiteral("Emergency stop buttons"));
    name(inputs, QStringLiteral("I0.13"), QStringLiteral("LightBeamSensor"),
         QStringLiteral("Light beam sensor"));
    name(inputs, QStringLiteral("I0.14"), QStringLiteral("ResetButton"),
         QStringLiteral("Push button for reset of light beam"));
    const QString outputs = QStringLiteral("Safety Outputs");
    name(outputs, QStringLiteral("Q0.2"), QStringLiteral("Contactor_A"),
         QStringLiteral("Safety output controlling contactor"));
    name(outputs, QStringLiteral("Q0.3"), QStringLiteral("Contactor_B"),
         QStringLiteral("Safety output controlling contactor"));
    name(QStringLiteral("NonSafety Outputs"), QStringLiteral("Q0.14"), QStringLiteral("IndReset"));
    name(QStringLiteral("Memories"), QStringLiteral("M0.0"), QStringLiteral("MutingActive"));

    // 3.10: a new network made of the muting block; its times stay at their
    // defaults, as the tutorial leaves Mute2's Test input unconnected.
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    page().view()->setFocus();
    QTest::keyClick(page().view(), Qt::Key_Insert);
    insertBlock(QStringLiteral("twosensor"), QStringLiteral("TwoSensorMuting"),
                {{QStringLiteral("Sensor1"), QStringLiteral("MuteSensor1")},
                 {QStringLiteral("Sensor2"), QStringLiteral("MuteSensor2")},
                 {QStringLiteral("Beam"), QStringLiteral("LightBeamSensor")},
                 {QStringLiteral("Muting"), QStringLiteral("MutingActive")}});

    // 3.12: the safety functions. A block network is the box alone, so the
    // contacts in front of the reset block are a network of their own.
    QTest::keyClick(page().view(), Qt::Key_Insert);
    insertNamingNew('L', QStringLiteral("M0.1"), QStringLiteral("ProtectionOk"));
    insert('C', QStringLiteral("EStopButton"));
    insert('C', QStringLiteral("LightBeamSensor"));
    QTest::keyClick(page().view(), '\\');
    insert('C', QStringLiteral("MutingActive"));
    QTest::keyClick(page().view(), Qt::Key_Insert);
    insertBlock(QStringLiteral("monitoredreset"), QStringLiteral("MonitoredReset"),
                {{QStringLiteral("Enable"), QStringLiteral("ProtectionOk")},
                 {QStringLiteral("Reset"), QStringLiteral("ResetButton")},
                 {QStringLiteral("Feedback"), QStringLiteral("ContMonitor")},
                 {QStringLiteral("Out"), QStringLiteral("Contactor_A")},
                 {QStringLiteral("ResetLamp"), QStringLiteral("IndReset")}});

    // 3.13: contactor B works exactly as contactor A.
    QTest::keyClick(page().view(), Qt::Key_Insert);
    insert('L', QStringLiteral("Contactor_B"));
    insert('C', QStringLiteral("Contactor_A"));
    ASSERT_EQ(page().networkCount(0), 4);

    const QByteArray drawn = projectText();
    EXPECT_TRUE(drawn.contains(";@block TwoSensorMuting Sensor1=\"MuteSensor1\" "
                               "Sensor2=\"MuteSensor2\" Beam=\"LightBeamSensor\" "
                               "Muting=\"MutingActive\" lib=\"Rungsmith_Basics\""))
        << drawn.toStdString();
    EXPECT_TRUE(drawn.contains("ProtectionOk = EStopButton * (LightBeamSensor + MutingActive)\n"))
        << drawn.toStdString();
    EXPECT_TRUE(drawn.contains(";@block MonitoredReset Enable=\"ProtectionOk\" "
                               "Reset=\"ResetButton\" Feedback=\"ContMonitor\" "
                               "Out=\"Contactor_A\" ResetLamp=\"IndReset\""))
        << drawn.toStdString();
    EXPECT_TRUE(drawn.contains("Contactor_B = Contactor_A\n")) << drawn.toStdString();

    // 3.4: saved, closed and opened again, it is the same project.
    const QString path = directory.filePath(QStringLiteral("tutorial.sps"));
    saveAs(path);
    ASSERT_TRUE(QFileInfo::exists(path));
    EXPECT_FALSE(document()->isModified());
    EXPECT_EQ(readFile(path), drawn);
    ASSERT_TRUE(window.closeDocument(document()));
    ASSERT_TRUE(window.loadFile(path).isEmpty());
    EXPECT_FALSE(document()->isModified()) << "the saved instances need no expanding";
    EXPECT_EQ(projectText(), drawn);
    clickNode({PageRef::Kind::Ladder, document(), 0, 0});
    ASSERT_EQ(page().networkCount(0), 4);
    ASSERT_TRUE(page().networkItem(0, 0)->layout().block.has_value());
    EXPECT_EQ(page().networkItem(0, 0)->layout().block->type, QStringLiteral("TwoSensorMuting"));
    EXPECT_FALSE(page().networkItem(0, 1)->layout().block.has_value());
    ASSERT_TRUE(page().networkItem(0, 2)->layout().block.has_value());
    EXPECT_EQ(page().networkItem(0, 2)->layout().block->type, QStringLiteral("MonitoredReset"));

    action("compileAction")->trigger();
    ASSERT_TRUE(waitForCompile());
    EXPECT_EQ(window.compileOutput()->closingLine(),
              QStringLiteral("0 Error(s) detected Result=OK"));

    // What the tutorial's program does: muting, and the reset.
    const rs::test::ProgramRun run =
        rs::test::runCli({QStringLiteral("test"), path,
                          QStringLiteral(RUNGSMITH_TEST_DATA "/tutorial/muting_tutorial.scn")});
    EXPECT_EQ(run.exitCode, 0) << run.outText().toStdString() << run.errText().toStdString();
    EXPECT_EQ(run.outText(), QStringLiteral("23 passed, 0 failed\n"))
        << run.outText().toStdString();
}

} // namespace
