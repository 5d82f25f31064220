// SPDX-License-Identifier: GPL-3.0-or-later
#include "WindowTest.h"

#include "document/ProjectDocument.h"
#include "output/CompileOutput.h"

#include <QAction>
#include <QTest>
#include <QUndoStack>

#include "QtPrinting.h"

#include <gtest/gtest.h>

// A project written with block instances but without their statements.

namespace {

const QByteArray kHandWritten =
    "! id_pluto:00=000000000000\n"
    "! type_pluto:00=A20,is3\n"
    "! I0.0=Door1A\n"
    "! I0.1=Door1B\n"
    "! pgm_pluto:00\n"
    "S0.0_0\n"
    ";@block EquivalentInputs Channel1=\"Door1A\" Channel2=\"Door1B\" Out=\"Q0.2\"\n"
    ";@end\n";

class BlockInstancesTest : public WindowTest {
protected:
    bool waitForCompile() {
        return QTest::qWaitFor([&] { return !window.isCompiling(); }, 30000);
    }
};

TEST_F(BlockInstancesTest, OpeningExpandsThemAsOneUndoableEditThatSavingWrites) {
    const QString path = writeFile(QStringLiteral("doors.sps"), kHandWritten);
    ASSERT_TRUE(window.loadFile(path).isEmpty());
    ASSERT_NE(document(), nullptr);
    EXPECT_TRUE(document()->isModified());
    const QByteArray expanded = projectText();
    EXPECT_TRUE(expanded.contains("lib=\"Rungsmith_Basics\" version=\"1.0\""))
        << expanded.toStdString();
    EXPECT_TRUE(expanded.contains("Q0.2 = Door1A * Door1B * /M0.")) << expanded.toStdString();
    EXPECT_EQ(readFile(path), kHandWritten) << "nothing is written before a save";

    document()->undoStack()->undo();
    EXPECT_EQ(projectText(), kHandWritten);
    document()->undoStack()->redo();
    EXPECT_EQ(projectText(), expanded);

    action("saveAction")->trigger();
    EXPECT_FALSE(document()->isModified());
    EXPECT_EQ(readFile(path), expanded);
}

TEST_F(BlockInstancesTest, ABadCallIsACompileErrorAtItsRecordAndTheRecordIsKept) {
    QByteArray text = kHandWritten;
    text.replace("Out=\"Q0.2\"", "Out=\"I0.5\"");
    const QString path = writeFile(QStringLiteral("bad.sps"), text);
    ASSERT_TRUE(window.loadFile(path).isEmpty());
    EXPECT_FALSE(document()->isModified());
    EXPECT_EQ(projectText(), text);
    showWindow();
    action("compileAction")->trigger();
    ASSERT_TRUE(waitForCompile());
    rs::ui::CompileOutput* output = window.compileOutput();
    EXPECT_EQ(output->closingLine(), QStringLiteral("1 Error(s) detected Result=FAILED"));
    bool found = false;
    using rs::ui::CompileOutput;
    for (int i = 0; i < output->rowCount(); ++i) {
        if (output->text(i, CompileOutput::MessageColumn)
                .contains(QStringLiteral("pin Out takes"))) {
            found = true;
            EXPECT_EQ(output->text(i, CompileOutput::PlaceColumn),
                      QStringLiteral("Pluto 0, line 3:62"))
                << output->text(i, CompileOutput::MessageColumn).toStdString();
        }
    }
    EXPECT_TRUE(found);
}

} // namespace
