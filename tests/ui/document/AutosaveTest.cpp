// SPDX-License-Identifier: GPL-3.0-or-later
#include "WindowTest.h"

#include "MessageBoxAnswerer.h"
#include "document/Autosave.h"
#include "document/ProjectDocument.h"
#include "pl110/Pl110Document.h"
#include "pl110/Pl110Window.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QTest>

#include "QtPrinting.h"

#include <gtest/gtest.h>

namespace {

const QByteArray kAutosaveProject = "$name Press\n"
                                    "! id_pluto:00=000000000000\n"
                                    "! pgm_pluto:00\n"
                                    "S0.0_0\n";

using AutosaveTest = WindowTest;

// The copies on disk, whoever holds them.
QStringList copyFiles() {
    return QDir(rs::ui::Autosave::directory()).entryList({QStringLiteral("*.sps")}, QDir::Files);
}

TEST_F(AutosaveTest, APl110ProgramsChangesAreRecoveredInAPl110Window) {
    const QByteArray program = "$target PL110\nMAIN\nQ1 = I1\n";
    const QString path = writeFile(QStringLiteral("station.sps"), program);
    {
        QString error;
        auto* crashed = new rs::ui::Pl110Window(rs::ui::Pl110Document::open(path, error));
        crashed->document()->setText(program + "Q2 = I2\n", QStringLiteral("Typing"));
        crashed->autosaveNow();
        ASSERT_EQ(copyFiles().size(), 1);
        delete crashed; // never closed: the copy stays
    }
    EXPECT_EQ(readFile(path), program);
    MessageBoxAnswerer recover(QMessageBox::Ok);
    ASSERT_EQ(window.recoverAutosaved(), 1);
    rs::ui::Pl110Window* recovered = nullptr;
    for (QWidget* widget : QApplication::topLevelWidgets())
        if (auto* pl110 = qobject_cast<rs::ui::Pl110Window*>(widget))
            recovered = pl110;
    ASSERT_NE(recovered, nullptr);
    EXPECT_EQ(recovered->document()->text(), program + "Q2 = I2\n");
    EXPECT_EQ(recovered->document()->path(), path);
    EXPECT_TRUE(recovered->document()->isModified());
    EXPECT_TRUE(window.currentDocument() == nullptr ||
                !window.currentDocument()->path().endsWith(QStringLiteral("station.sps")));
    // Saving puts the work where it belongs and the copy goes.
    recovered->findChild<QAction*>(QStringLiteral("pl110SaveAction"))->trigger();
    EXPECT_FALSE(recovered->document()->isModified());
    EXPECT_EQ(readFile(path), program + "Q2 = I2\n");
    EXPECT_TRUE(copyFiles().isEmpty());
    recovered->close();
}

TEST_F(AutosaveTest, ACrashedSessionsChangesAreRecovered) {
    const QString path = writeFile(QStringLiteral("press.sps"), kAutosaveProject);
    QByteArray changed;
    {
        // The session that "crashes": its window is never closed, so its copy stays.
        auto* crashed = new rs::ui::MainWindow;
        ASSERT_TRUE(crashed->loadFile(path).isEmpty());
        crashed->currentDocument()->edit(QStringLiteral("Describe"), [](rs::project::Project& p) {
            p.description = "work in progress";
        });
        changed = crashed->currentDocument()->fileText();
        crashed->autosaveNow();
        ASSERT_EQ(copyFiles().size(), 1);
        // A copy of a window still running is not offered.
        EXPECT_EQ(window.recoverAutosaved(), 0);
        delete crashed;
    }
    EXPECT_EQ(readFile(path), kAutosaveProject);

    MessageBoxAnswerer recover(QMessageBox::Ok); // no such button: the default, Recover
    ASSERT_EQ(window.recoverAutosaved(), 1);
    EXPECT_TRUE(recover.answered());
    EXPECT_TRUE(recover.informativeText().contains(QStringLiteral("press.sps")));
    rs::ui::ProjectDocument* recovered = window.currentDocument();
    ASSERT_NE(recovered, nullptr);
    EXPECT_EQ(recovered->fileText(), changed);
    EXPECT_EQ(recovered->path(), path);
    EXPECT_TRUE(recovered->isModified());

    // Saving puts the work where it belongs and the copy goes.
    action("saveAction")->trigger();
    EXPECT_EQ(readFile(path), changed);
    EXPECT_TRUE(rs::ui::Autosave::copies().isEmpty());
}

TEST_F(AutosaveTest, UnmodifiedProjectsHaveNoCopyAndDiscardingRemovesThem) {
    ASSERT_TRUE(
        window.loadFile(writeFile(QStringLiteral("press.sps"), kAutosaveProject)).isEmpty());
    window.autosaveNow();
    EXPECT_TRUE(copyFiles().isEmpty());
    window.currentDocument()->edit(QStringLiteral("Describe"),
                                   [](rs::project::Project& p) { p.description = "x"; });
    window.autosaveNow();
    ASSERT_EQ(copyFiles().size(), 1);
    EXPECT_TRUE(rs::ui::Autosave::copies().isEmpty()); // this window is running
    // Undo back to the saved state: nothing to recover any more.
    action("undoAction")->trigger();
    EXPECT_TRUE(copyFiles().isEmpty());
}

} // namespace
