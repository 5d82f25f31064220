// SPDX-License-Identifier: GPL-3.0-or-later
#include "WindowTest.h"

#include "document/Autosave.h"
#include "document/ProjectDocument.h"
#include "shell/ProjectTree.h"
#include "text/TextPage.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QSettings>
#include <QTest>

void WindowTest::SetUp() {
    // Each test starts from no recent files, saved layout or preferences.
    QSettings().clear();
    ASSERT_TRUE(directory.isValid());
    rs::ui::Autosave::setDirectory(directory.filePath(QStringLiteral("autosave")));
}

void WindowTest::TearDown() {
    // Nothing modified is left behind, so closing asks nothing.
    if (window.textPage()->hasErrors())
        window.textPage()->discardChanges();
    for (rs::ui::ProjectDocument* document : window.documents())
        document->saveTo(directory.filePath(
            QStringLiteral("left-behind-%1.sps").arg(reinterpret_cast<quintptr>(document))));
    window.close();
}

QString WindowTest::writeFile(const QString& name, const QByteArray& bytes) {
    QFile file(directory.filePath(name));
    EXPECT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(bytes);
    return file.fileName();
}

QByteArray WindowTest::readFile(const QString& path) {
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << path.toStdString();
    return file.readAll();
}

void WindowTest::showWindow() {
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    activate();
}

void WindowTest::activate() {
    // Menu shortcuts answer only in the active window.
    window.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
}

QAction* WindowTest::action(const char* name) {
    auto* found = window.findChild<QAction*>(QString::fromLatin1(name));
    EXPECT_NE(found, nullptr) << name;
    return found;
}

QByteArray WindowTest::projectText() {
    return document() ? document()->fileText() : QByteArray();
}

void WindowTest::clickNode(const rs::ui::PageRef& page) {
    rs::ui::ProjectTree* tree = window.projectTree();
    QTreeWidgetItem* item = tree->itemFor(page);
    ASSERT_NE(item, nullptr);
    tree->scrollToItem(item);
    const QPoint where = tree->visualItemRect(item).center();
    QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, where);
}
