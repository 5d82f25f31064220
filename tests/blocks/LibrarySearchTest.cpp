// SPDX-License-Identifier: GPL-3.0-or-later
#include "blocks/LibrarySearch.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace rs::blocks;

namespace {

void write(const QString& path, const std::string& libraryName, const std::string& blockName) {
    QDir().mkpath(QFileInfo(path).path());
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    const std::string text = "rungsmith-library 1\nlibrary " + libraryName + "\nversion 1\nblock " +
                             blockName +
                             "\nkind macro\nversion 1\ndescription en x\nbody Q0.0 = I0.0\n";
    file.write(text.c_str());
}

} // namespace

TEST(LibrarySearch, LooksBesideTheBinaryThenInTheInstalledShareFolder) {
    QTemporaryDir root;
    const QString bin = root.filePath(QStringLiteral("bin"));
    QDir().mkpath(bin + QStringLiteral("/libraries"));
    QDir().mkpath(root.filePath(QStringLiteral("share/rungsmith/libraries")));
    const QStringList folders = standardLibraryFolders(bin);
    ASSERT_GE(folders.size(), 2);
    EXPECT_EQ(folders[0], QDir(bin + QStringLiteral("/libraries")).canonicalPath());
    EXPECT_EQ(folders[1],
              QDir(root.filePath(QStringLiteral("share/rungsmith/libraries"))).canonicalPath());
    for (const QString& folder : folders.mid(2))
        EXPECT_EQ(folder, QStringLiteral("/usr/share/rungsmith/libraries"));
}

TEST(LibrarySearch, LeavesOutFoldersThatDoNotExist) {
    QTemporaryDir root;
    const QStringList folders = standardLibraryFolders(root.filePath(QStringLiteral("bin")));
    for (const QString& folder : folders)
        EXPECT_EQ(folder, QStringLiteral("/usr/share/rungsmith/libraries"));
}

TEST(LibrarySearch, StandardThenProjectThenGivenFilesAndTheFirstOfANameWins) {
    QTemporaryDir root;
    const QString standard = root.filePath(QStringLiteral("standard"));
    const QString project = root.filePath(QStringLiteral("project"));
    write(standard + QStringLiteral("/b.rslib"), "Beta", "Second");
    write(standard + QStringLiteral("/a.rslib"), "Alpha", "First");
    write(standard + QStringLiteral("/ignored.txt"), "Ignored", "Never");
    write(project + QStringLiteral("/mine.rslib"), "Mine", "Own");
    write(project + QStringLiteral("/shadow.rslib"), "ALPHA", "Shadow");
    const QString given = root.filePath(QStringLiteral("elsewhere/given.rslib"));
    write(given, "Given", "First");

    const LibrarySet set = loadLibraries({standard}, project, {given});
    ASSERT_EQ(set.libraries.size(), 4u);
    EXPECT_EQ(set.libraries[0].library.name, "Alpha");
    EXPECT_EQ(set.libraries[0].origin, LibraryOrigin::Standard);
    EXPECT_EQ(set.libraries[1].library.name, "Beta");
    EXPECT_EQ(set.libraries[2].library.name, "Mine");
    EXPECT_EQ(set.libraries[2].origin, LibraryOrigin::User);
    EXPECT_EQ(set.libraries[3].library.name, "Given");
    EXPECT_EQ(set.libraryOfBlock("first")->library.name, "Alpha");
    EXPECT_EQ(set.findLibrary("mine")->path, project + QStringLiteral("/mine.rslib"));
    EXPECT_TRUE(set.ok()); // a shadowed library is a warning, not an error
    ASSERT_EQ(set.problems.size(), 1u);
    EXPECT_EQ(set.problems[0].path, project + QStringLiteral("/shadow.rslib"));
    EXPECT_EQ(set.problems[0].diagnostics[0].severity, rs::lang::Severity::Warning);
}

TEST(LibrarySearch, ReportsUnreadableAndBadFiles) {
    QTemporaryDir root;
    const QString bad = root.filePath(QStringLiteral("bad.rslib"));
    QFile file(bad);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("rungsmith-library 1\nlibrary Bad\n");
    file.close();
    const LibrarySet set =
        loadLibraries({}, {}, {bad, root.filePath(QStringLiteral("missing.rslib"))});
    EXPECT_TRUE(set.libraries.empty());
    EXPECT_FALSE(set.ok());
    ASSERT_EQ(set.problems.size(), 2u);
    EXPECT_EQ(set.problems[0].diagnostics.size(), 1u);
    EXPECT_TRUE(set.problems[1].readError.startsWith(QStringLiteral("cannot read ")));
}
