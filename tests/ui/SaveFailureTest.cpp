#include "WindowTest.h"

#include "Autosave.h"
#include "CompileOutput.h"
#include "MessageBoxAnswerer.h"
#include "ProjectDocument.h"
#include "ladder/LadderPage.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTest>

#include "QtPrinting.h"

#include <gtest/gtest.h>

#include <unistd.h>

// A save or export that cannot be completed says so, leaves the file it
// would have replaced as it was, and keeps the project modified and its
// autosave copy.

namespace {

const QString kMuting = QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps");

class SaveFailureTest : public WindowTest {
protected:
    // Opens a copy of the muting example from `folder` and changes it.
    void openAndEdit(const QString& folder) {
        path = QDir(folder).filePath(QStringLiteral("muting.sps"));
        ASSERT_TRUE(QFile::copy(kMuting, path));
        saved = readFile(path);
        ASSERT_TRUE(window.loadFile(path).isEmpty());
        document()->edit(QStringLiteral("Describe"),
                         [this](rs::project::Project& p) { p.description = description; });
        window.autosaveNow();
        ASSERT_EQ(copies().size(), 1);
    }
    QStringList copies() const {
        return QDir(rs::ui::Autosave::directory())
            .entryList({QStringLiteral("*.sps")}, QDir::Files);
    }
    // Saving failed: the message said it, nothing on disk changed, the work is kept.
    void expectNothingLost(const MessageBoxAnswerer& box) {
        EXPECT_TRUE(box.answered());
        EXPECT_TRUE(document()->isModified());
        EXPECT_EQ(readFile(path), saved);
        EXPECT_EQ(copies().size(), 1);
    }

    QString path;
    QByteArray saved;
    std::string description = "changed";
};

TEST_F(SaveFailureTest, SaveAsWhereNoFileCanBeLeavesTheProjectModified) {
    openAndEdit(directory.path());
    {
        MessageBoxAnswerer box(QMessageBox::Ok);
        EXPECT_FALSE(window.saveDocumentAs(document(), directory.filePath("no/such/folder/x.sps")));
        expectNothingLost(box);
        EXPECT_TRUE(box.text().contains(QStringLiteral("x.sps")));
    }
    QDir(directory.path()).mkdir(QStringLiteral("folder.sps"));
    {
        MessageBoxAnswerer box(QMessageBox::Ok);
        EXPECT_FALSE(window.saveDocumentAs(document(), directory.filePath("folder.sps")));
        expectNothingLost(box);
        EXPECT_TRUE(QFileInfo(directory.filePath("folder.sps")).isDir());
    }
    EXPECT_EQ(document()->path(), QFileInfo(path).absoluteFilePath());
}

TEST_F(SaveFailureTest, APdfThatCannotBeWrittenIsSaidAndAnOldOneKept) {
    window.loadFile(kMuting);
    ASSERT_TRUE(window.showPage({rs::ui::PageRef::Kind::Ladder, document(), 0, 0}));
    const QString folder = directory.filePath(QStringLiteral("taken.pdf"));
    QDir(directory.path()).mkdir(QStringLiteral("taken.pdf"));
    MessageBoxAnswerer box(QMessageBox::Ok);
    EXPECT_FALSE(window.ladderPage()->exportPdf(folder));
    EXPECT_TRUE(box.answered());
    EXPECT_TRUE(QFileInfo(folder).isDir());
    EXPECT_TRUE(window.ladderPage()->message().contains(QStringLiteral("Could not")))
        << window.ladderPage()->message().toStdString();
}

TEST_F(SaveFailureTest, ACompiledFileThatCannotBeWrittenIsInTheOutput) {
    openAndEdit(directory.path());
    QDir(directory.path()).mkdir(QStringLiteral("muting.hps")); // where the image would go
    MessageBoxAnswerer box(QMessageBox::Ok);
    action("compileAction")->trigger();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !window.isCompiling(); }, 30000));
    EXPECT_TRUE(box.answered());
    bool said = false;
    rs::ui::CompileOutput* output = window.compileOutput();
    for (int i = 0; i < output->topLevelItemCount(); ++i)
        said |= output->topLevelItem(i)
                    ->text(rs::ui::CompileOutput::MessageColumn)
                    .contains(QStringLiteral("not written"));
    EXPECT_TRUE(said);
    EXPECT_TRUE(QFileInfo(directory.filePath("muting.hps")).isDir());
    EXPECT_TRUE(document()->isModified());
}

// A disk that fills up while the project is written: a small tmpfs, which
// only root may mount; elsewhere the test says why it did not run.
class FullDiskTest : public SaveFailureTest {
protected:
    void SetUp() override {
        SaveFailureTest::SetUp();
        disk = directory.filePath(QStringLiteral("disk"));
        QDir().mkpath(disk);
        if (geteuid() != 0 ||
            QProcess::execute(QStringLiteral("mount"),
                              {QStringLiteral("-t"), QStringLiteral("tmpfs"), QStringLiteral("-o"),
                               QStringLiteral("size=64k"), QStringLiteral("tmpfs"), disk}) != 0)
            GTEST_SKIP() << "cannot mount a small tmpfs here (needs root)";
        mounted = true;
    }
    void TearDown() override {
        SaveFailureTest::TearDown();
        if (mounted)
            QProcess::execute(QStringLiteral("umount"), {disk});
    }
    QString disk;
    bool mounted = false;
};

TEST_F(FullDiskTest, SavingAProjectLargerThanTheDiskKeepsTheOldFile) {
    description = std::string(200 * 1024, 'x'); // more than the disk holds
    openAndEdit(disk);
    MessageBoxAnswerer box(QMessageBox::Ok);
    action("saveAction")->trigger();
    expectNothingLost(box);
    EXPECT_EQ(QDir(disk).entryList(QDir::Files), QStringList{QStringLiteral("muting.sps")});
}

} // namespace
