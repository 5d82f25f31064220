// SPDX-License-Identifier: GPL-3.0-or-later
#include "WindowTest.h"

#include "document/ProjectDocument.h"
#include "pages/VariableTableModel.h"
#include "pages/VariablesPage.h"
#include "project/VariableTable.h"

#include <QLabel>

#include "QtPrinting.h"

#include <gtest/gtest.h>

// The pages of a unit show what its block instances use: the Variables page
// marks their pins' operands and private variables as used and says by which
// block, the I/O Options page says which pin a terminal is bound to, and the
// unit page counts them against the unit's timers, memories and registers.

namespace {

using rs::ui::PageRef;
using rs::ui::VariableTableModel;

// EquivalentInputs as Rungsmith_Basics expands it, and a private variable
// (#spare) that no statement uses: it is the instance's all the same.
const QByteArray kInstancesProject =
    "! id_pluto:00=000000000000\n"
    "! type_pluto:00=A20,is3\n"
    "! I0.0=Door1A\n"
    "! pgm_pluto:00\n"
    "S0.0_0\n"
    ";@block EquivalentInputs Channel1=\"Door1A\" Channel2=\"I0.12\" Out=\"Q0.2\" "
    "lib=\"Rungsmith_Basics\" version=\"1.0\" #pin.Fault=\"M0.599\" #fault=\"M0.598\" "
    "#spare=\"R0.149\"\n"
    "S(M0.598) = (Door1A * /I0.12 + /Door1A * I0.12) * TON(0s50)\n"
    "R(M0.598) = /Door1A * /I0.12\n"
    "Q0.2 = Door1A * I0.12 * /M0.598\n"
    "M0.599 = M0.598\n"
    ";@end\n";

class InstanceVariablesPagesTest : public WindowTest {
protected:
    void SetUp() override {
        WindowTest::SetUp();
        ASSERT_TRUE(
            window.loadFile(writeFile(QStringLiteral("doors.sps"), kInstancesProject)).isEmpty());
        showWindow();
    }

    // The Variables page's cell of the variable, as the table shows it.
    QVariant cell(const char* address, VariableTableModel::Column column,
                  int role = Qt::DisplayRole) {
        const rs::lang::Address variable = rs::lang::readAddressWord(address).address;
        EXPECT_TRUE(window.variablesPage()->showVariable(variable)) << address;
        VariableTableModel* model = window.variablesPage()->model();
        for (int row = 0; row < model->rowCount(); ++row)
            if (model->variableAt(row)->address == variable)
                return model->data(model->index(row, column), role);
        ADD_FAILURE() << address << " is not listed";
        return {};
    }

    QString label(const QString& name) {
        auto* found = window.findChild<QLabel*>(name);
        EXPECT_NE(found, nullptr) << name.toStdString();
        return found ? found->text() : QString();
    }
};

TEST_F(InstanceVariablesPagesTest, TheVariablesPageShowsAPrivateVariableAsUsedByItsBlock) {
    ASSERT_TRUE(window.showPage(PageRef::Kind::Variables, 0));
    EXPECT_EQ(cell("M0.598", VariableTableModel::DescriptionColumn).toString(),
              QStringLiteral("Private variable #fault of block EquivalentInputs (line 3)"));
    EXPECT_EQ(cell("M0.598", VariableTableModel::StatusColumn, Qt::DisplayRole).toString(), "used");
    EXPECT_EQ(cell("M0.598", VariableTableModel::StatusColumn, Qt::ToolTipRole).toString(),
              QStringLiteral("Used in the code of the unit\n"
                             "Private variable #fault of block EquivalentInputs (line 3)"));

    // No statement uses it, yet it is the instance's.
    EXPECT_EQ(cell("R0.149", VariableTableModel::StatusColumn, Qt::DisplayRole).toString(), "used");
    EXPECT_EQ(cell("R0.149", VariableTableModel::StatusColumn, Qt::ToolTipRole).toString(),
              QStringLiteral("Private variable #spare of block EquivalentInputs (line 3)"));

    EXPECT_EQ(cell("I0.0", VariableTableModel::DescriptionColumn).toString(),
              QStringLiteral("Pin Channel1 of block EquivalentInputs (line 3)"));
    EXPECT_TRUE(cell("M0.597", VariableTableModel::StatusColumn, Qt::DisplayRole).isNull());
    EXPECT_TRUE(cell("M0.597", VariableTableModel::DescriptionColumn).toString().isEmpty());
}

TEST_F(InstanceVariablesPagesTest, ADescriptionOfItsOwnTakesThePlaceOfTheBlocksUse) {
    ASSERT_TRUE(window.showPage(PageRef::Kind::Variables, 0));
    const rs::lang::Address fault = rs::lang::readAddressWord("M0.598").address;
    document()->edit(QStringLiteral("Describe"), [&](rs::project::Project& p) {
        rs::project::setVariableDescription(p, fault, "Door fault");
    });
    EXPECT_EQ(cell("M0.598", VariableTableModel::DescriptionColumn).toString(),
              QStringLiteral("Door fault"));
    EXPECT_TRUE(cell("M0.598", VariableTableModel::StatusColumn, Qt::ToolTipRole)
                    .toString()
                    .contains(QStringLiteral("#fault of block EquivalentInputs")));
}

TEST_F(InstanceVariablesPagesTest, TheIoOptionsPageSaysWhichPinATerminalIsBoundTo) {
    ASSERT_TRUE(window.showPage(PageRef::Kind::IoOptions, 0));
    EXPECT_EQ(label(QStringLiteral("instanceUses:I0.0")),
              QStringLiteral("Pin Channel1 of block EquivalentInputs (line 3)"));
    EXPECT_EQ(label(QStringLiteral("instanceUses:IQ0.12")),
              QStringLiteral("Pin Channel2 of block EquivalentInputs (line 3)"));
    EXPECT_EQ(label(QStringLiteral("instanceUses:I0.1")), QString());
}

TEST_F(InstanceVariablesPagesTest, TheUnitPageCountsThemAgainstTheUnitsLimits) {
    ASSERT_TRUE(window.showPage(PageRef::Kind::Unit, 0));
    EXPECT_EQ(label(QStringLiteral("timersUsedLabel")),
              QStringLiteral("1 of 50 (1 of them by block instances)"));
    EXPECT_TRUE(label(QStringLiteral("memoriesUsedLabel"))
                    .endsWith(QStringLiteral("(2 of them by block instances)")));
    EXPECT_TRUE(label(QStringLiteral("memoriesUsedLabel")).startsWith(QStringLiteral("2 of ")));
    EXPECT_EQ(label(QStringLiteral("registersUsedLabel")),
              QStringLiteral("1 of 150 (1 of them by block instances)"));

    // Without the instance nothing is taken: the page follows the project.
    document()->edit(QStringLiteral("Remove"), [](rs::project::Project& p) {
        p.program.units.front().steps.front().lines.clear();
    });
    EXPECT_EQ(label(QStringLiteral("timersUsedLabel")), QStringLiteral("0 of 50"));
    EXPECT_EQ(label(QStringLiteral("registersUsedLabel")), QStringLiteral("0 of 150"));
}

} // namespace
