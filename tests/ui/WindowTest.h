// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "shell/MainWindow.h"
#include "shell/PageRef.h"

#include <QByteArray>
#include <QString>
#include <QTemporaryDir>

#include <gtest/gtest.h>

class QAction;

namespace rs::ui {
class ProjectDocument;
}

// A main window of its own for each test, with a scratch folder for files and
// for autosave copies, and no recent files or settings from other tests.
class WindowTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;

    QString writeFile(const QString& name, const QByteArray& bytes);
    static QByteArray readFile(const QString& path);
    void showWindow();
    void activate();
    QAction* action(const char* name);
    // The current project's canonical text.
    QByteArray projectText();
    rs::ui::ProjectDocument* document() { return window.currentDocument(); }
    // Clicks the node of a page in the project tree, as a user does.
    void clickNode(const rs::ui::PageRef& page);

    QTemporaryDir directory;
    rs::ui::MainWindow window;
};
