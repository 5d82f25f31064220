// SPDX-License-Identifier: GPL-3.0-or-later
#include "WindowTest.h"

#include "document/ProjectDocument.h"

#include <QAction>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QUndoStack>

#include "QtPrinting.h"

#include <gtest/gtest.h>

// The project page's function libraries: which the project uses, chosen from
// those installed, undoable, and what reading the project then takes.

namespace {

using rs::ui::PageRef;

const QByteArray kLibrariesProject = "! id_pluto:00=000000000000\n"
                                     "! pgm_pluto:00\n"
                                     "S0.0_0\n"
                                     "Q0.2 = I0.0\n";

class ProjectLibrariesTest : public WindowTest {
protected:
    void SetUp() override {
        WindowTest::SetUp();
        ASSERT_TRUE(
            window.loadFile(writeFile(QStringLiteral("p.sps"), kLibrariesProject)).isEmpty());
        showWindow();
        window.showPage(PageRef::Kind::Project, -1);
        list = window.findChild<QListWidget*>(QStringLiteral("projectLibrariesList"));
        addStandard = window.findChild<QPushButton*>(QStringLiteral("addStandardLibraryButton"));
        remove = window.findChild<QPushButton*>(QStringLiteral("removeLibraryButton"));
        ASSERT_NE(list, nullptr);
        ASSERT_NE(addStandard, nullptr);
        ASSERT_NE(remove, nullptr);
    }
    QAction* offered(const QString& name) {
        QMenu* menu = addStandard->menu();
        emit menu->aboutToShow();
        for (QAction* action : menu->actions())
            if (action->text() == name)
                return action;
        return nullptr;
    }

    QListWidget* list = nullptr;
    QPushButton* addStandard = nullptr;
    QPushButton* remove = nullptr;
};

TEST_F(ProjectLibrariesTest, AStandardLibraryIsAddedFromTheInstalledOnesAndRemovedWithUndo) {
    ASSERT_EQ(list->count(), 1);
    EXPECT_FALSE(list->item(0)->flags() & Qt::ItemIsSelectable) << "a note, not a library";
    EXPECT_FALSE(remove->isEnabled());

    QAction* basics = offered(QStringLiteral("Rungsmith_Basics"));
    ASSERT_NE(basics, nullptr);
    ASSERT_TRUE(basics->isEnabled());
    basics->trigger();
    const std::vector<std::string> used{"Rungsmith_Basics"};
    EXPECT_EQ(document()->project().libraries, used);
    EXPECT_TRUE(projectText().startsWith(";@project library=\"Rungsmith_Basics\"\n"))
        << projectText().toStdString();
    ASSERT_EQ(list->count(), 1);
    EXPECT_EQ(list->item(0)->text(), QStringLiteral("Rungsmith_Basics"));
    EXPECT_FALSE(offered(QStringLiteral("Rungsmith_Basics"))->isEnabled()) << "used already";

    ASSERT_TRUE(remove->isEnabled());
    remove->click();
    EXPECT_TRUE(document()->project().libraries.empty());
    document()->undoStack()->undo();
    EXPECT_EQ(document()->project().libraries, used);
    document()->undoStack()->undo();
    EXPECT_TRUE(document()->project().libraries.empty());
    EXPECT_EQ(projectText(), kLibrariesProject);
}

TEST_F(ProjectLibrariesTest, ALibraryThatIsNotInstalledIsShownAsNotFound) {
    document()->edit(QStringLiteral("Use"),
                     [](rs::project::Project& p) { p.libraries = {"Gone"}; });
    ASSERT_EQ(list->count(), 1);
    EXPECT_EQ(list->item(0)->text(), QStringLiteral("Gone (not found)"));
}

} // namespace
