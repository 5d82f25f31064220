// SPDX-License-Identifier: GPL-3.0-or-later
#include "WindowTest.h"

#include "MessageBoxAnswerer.h"
#include "document/ProjectDocument.h"
#include "document/ProjectMerging.h"
#include "project/UnitText.h"

#include <gtest/gtest.h>

namespace {

using rs::ui::ProjectDocument;

const QString kMergingPressLine =
    QStringLiteral(RUNGSMITH_SOURCE_DIR "/resources/examples/press-line.sps");

const QByteArray kCell = "$name Cell\n"
                         "! id_pluto:02=000000000002\n"
                         "! type_pluto:02=A20,is3\n"
                         "! I2.0=CellStart\n"
                         "! pgm_pluto:02\n"
                         "S2.0_0\n"
                         "Q2.2 = CellStart\n";

class ProjectMergingTest : public WindowTest {
protected:
    // Opens the files in this order; the documents as the window holds them.
    std::vector<ProjectDocument*> open(const QStringList& files) {
        for (const QString& file : files)
            EXPECT_TRUE(window.loadFile(file).isEmpty()) << file.toStdString();
        return window.documents();
    }
};

// Issue 19 (manual Part 1, 12.2): the units of another open project join
// this one as one undo step.
TEST_F(ProjectMergingTest, TheOtherProjectsUnitsJoinAsOneUndoStep) {
    const auto documents = open({kMergingPressLine, writeFile(QStringLiteral("cell.sps"), kCell)});
    ASSERT_EQ(documents.size(), 2u);
    ProjectDocument* into = documents[0];
    const int steps = into->undoStack()->count();
    EXPECT_EQ(rs::ui::mergeOpenProject(&window, into, documents[1], false),
              QStringLiteral("cell.sps is merged into press-line.sps."));
    EXPECT_EQ(into->project().stations(), (std::vector<int>{0, 1, 2}));
    EXPECT_NE(rs::project::unitText(into->project(), 2).find("Q2.2 = CellStart"),
              std::string::npos);
    EXPECT_EQ(into->undoStack()->count(), steps + 1);
    into->undoStack()->undo();
    EXPECT_EQ(into->project().stations(), (std::vector<int>{0, 1}));
}

// A station both use is a conflict: the message lists it and nothing changes.
TEST_F(ProjectMergingTest, AConflictIsListedAndNothingMerges) {
    const auto documents =
        open({kMergingPressLine,
              writeFile(QStringLiteral("copy.sps"),
                        readFile(kMergingPressLine).replace("$name Press line", "$name Copy"))});
    ASSERT_EQ(documents.size(), 2u);
    ProjectDocument* into = documents[0];
    const rs::project::Project before = into->project();
    MessageBoxAnswerer answerer(QMessageBox::Ok);
    EXPECT_TRUE(rs::ui::mergeOpenProject(&window, into, documents[1], true).isEmpty());
    ASSERT_TRUE(answerer.answered());
    EXPECT_TRUE(
        answerer.informativeText().contains(QStringLiteral("station 0 is in both projects")))
        << answerer.informativeText().toStdString();
    EXPECT_TRUE(answerer.informativeText().contains(QStringLiteral("the name 'EStopA'")))
        << answerer.informativeText().toStdString();
    EXPECT_EQ(into->project(), before);
    EXPECT_FALSE(into->undoStack()->canUndo());
}

} // namespace
