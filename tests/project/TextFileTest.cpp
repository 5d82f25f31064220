// SPDX-License-Identifier: GPL-3.0-or-later
#include "FullFileSystem.h"
#include "project/ProjectFile.h"
#include "project/WriteBehind.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>
#include <string_view>

using rs::project::readTextFile;
using rs::project::writeTextFile;
using rs::test::FullFileSystem;

namespace {

QByteArray readAll(const QString& path) {
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << path.toStdString();
    return file.readAll();
}

QString write(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes) {
    QFile file(dir.filePath(name));
    EXPECT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(bytes);
    return file.fileName();
}

#define REQUIRE_FULL_DISK(disk)                                                                    \
    if (!(disk).available())                                                                       \
    GTEST_SKIP() << (disk).reason().toStdString()

} // namespace

// The text stays in QSaveFile's buffer until commit; a full disk then showed
// only there, and Qt committed an empty file over the old one.
TEST(TextFile, SavingASmallTextToAFullDiskKeepsTheOldFile) {
    FullFileSystem disk;
    REQUIRE_FULL_DISK(disk);
    const QByteArray old = "! pgm_pluto:00\nS0.0_0\nQ0.0 = I0.0\n";
    ASSERT_TRUE(disk.put("project.sps", old));
    ASSERT_TRUE(disk.fill());
    const QString path = disk.filePath("project.sps");
    const QString error = writeTextFile(path, std::string(4000, 'x'));
    EXPECT_TRUE(error.startsWith("cannot write " + path + ": ")) << error.toStdString();
    EXPECT_EQ(readAll(path), old);
    EXPECT_EQ(QDir(disk.filePath(".")).entryList(QDir::Files | QDir::Hidden).size(), 2)
        << "the temporary copy is removed";
}

TEST(TextFile, SavingALargeTextToAFullDiskKeepsTheOldFile) {
    FullFileSystem disk;
    REQUIRE_FULL_DISK(disk);
    ASSERT_TRUE(disk.put("image.hps", "old"));
    ASSERT_TRUE(disk.fill());
    EXPECT_FALSE(writeTextFile(disk.filePath("image.hps"), std::string(1 << 20, 'x')).isEmpty());
    EXPECT_EQ(readAll(disk.filePath("image.hps")), "old");
}

TEST(TextFile, SavingANewFileToAFullDiskLeavesNoFile) {
    FullFileSystem disk;
    REQUIRE_FULL_DISK(disk);
    ASSERT_TRUE(disk.fill());
    EXPECT_FALSE(writeTextFile(disk.filePath("new.sps"), "Q0.0 = I0.0\n").isEmpty());
    EXPECT_FALSE(QFile::exists(disk.filePath("new.sps")));
}

TEST(TextFile, SavingWithRoomWritesEveryByte) {
    FullFileSystem disk;
    REQUIRE_FULL_DISK(disk);
    EXPECT_TRUE(writeTextFile(disk.filePath("p.sps"), "Q0.0 = I0.0\n").isEmpty());
    EXPECT_EQ(readAll(disk.filePath("p.sps")), "Q0.0 = I0.0\n");
}

// A large image is written while it is made; on a full disk the pieces after
// the first failure are not tried, and the old file stays.
TEST(TextFile, SavingPiecesToAFullDiskKeepsTheOldFile) {
    FullFileSystem disk;
    REQUIRE_FULL_DISK(disk);
    ASSERT_TRUE(disk.put("image.hps", "old"));
    ASSERT_TRUE(disk.fill());
    int pieces = 0;
    const QString error =
        writeTextFile(disk.filePath("image.hps"), [&](const rs::project::TextSink& sink) {
            for (; pieces < 64; ++pieces)
                sink(std::string(64 * 1024, 'x'));
        });
    EXPECT_FALSE(error.isEmpty());
    EXPECT_EQ(pieces, 64);
    EXPECT_EQ(readAll(disk.filePath("image.hps")), "old");
}

// Room for a megabyte and a half: the first megabyte is written and put on
// its way to the disk, then the disk fills; the old file stays.
TEST(TextFile, SavingPiecesToADiskThatFillsPartWayKeepsTheOldFile) {
    FullFileSystem disk(4096);
    REQUIRE_FULL_DISK(disk);
    ASSERT_TRUE(disk.put("image.hps", "old"));
    ASSERT_TRUE(disk.put("room", QByteArray(1536 * 1024, 'r')));
    ASSERT_TRUE(disk.fill());
    ASSERT_TRUE(QFile::remove(disk.filePath("room")));
    const QString path = disk.filePath("image.hps");
    const QString error = writeTextFile(path, [](const rs::project::TextSink& sink) {
        for (int i = 0; i < 64; ++i)
            sink(std::string(64 * 1024, 'x'));
    });
    EXPECT_TRUE(error.startsWith("cannot write " + path + ": ")) << error.toStdString();
    EXPECT_EQ(readAll(path), "old");
    EXPECT_EQ(QDir(disk.filePath(".")).entryList(QDir::Files | QDir::Hidden).size(), 2)
        << "the temporary copy is removed";
}

TEST(TextFile, SavingPiecesWritesThemInOrder) {
    QTemporaryDir dir;
    const QString path = dir.filePath("p.hps");
    EXPECT_TRUE(writeTextFile(path, [](const rs::project::TextSink& sink) {
                    sink("one ");
                    sink("");
                    sink("two");
                }).isEmpty());
    EXPECT_EQ(readAll(path), "one two");
}

// The pieces are written on another thread while the next ones are made:
// hundreds of them, of every size, some empty, cross the queue and the
// write-back steps and arrive whole and in order.
TEST(TextFile, SavingManyPiecesOfEverySizeKeepsTheirOrder) {
    QTemporaryDir dir;
    const QString path = dir.filePath("p.hps");
    std::mt19937 random(23);
    std::string expected;
    EXPECT_TRUE(writeTextFile(path, [&](const rs::project::TextSink& sink) {
                    std::string piece;
                    for (int i = 0; i < 600; ++i) {
                        const std::size_t size = random() % 3 == 0 ? 0 : random() % 70000;
                        piece.assign(size, static_cast<char>('a' + i % 26));
                        if (!piece.empty())
                            piece.front() = static_cast<char>('0' + i % 10);
                        expected += piece;
                        sink(piece); // the same buffer again at once: the sink keeps a copy
                    }
                }).isEmpty());
    ASSERT_GT(expected.size(), 2 * rs::project::WriteBehind::kWriteBackStep);
    const QByteArray written = readAll(path);
    ASSERT_EQ(static_cast<std::size_t>(written.size()), expected.size());
    EXPECT_TRUE(std::string_view(written.constData(), expected.size()) == expected);
}

// An image the writer refuses part way (issue 13) leaves the old file and no
// temporary copy beside it.
TEST(TextFile, AWriterThatThrowsLeavesTheOldFile) {
    QTemporaryDir dir;
    const QString path = write(dir, "image.hps", "old");
    EXPECT_THROW(writeTextFile(path,
                               [](const rs::project::TextSink& sink) {
                                   sink("new");
                                   throw std::invalid_argument("refused");
                               }),
                 std::invalid_argument);
    EXPECT_EQ(readAll(path), "old");
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 1);
}

// Refused after more pieces than wait in the queue: those still waiting are
// dropped, and the old file stays.
TEST(TextFile, AWriterThatThrowsLateLeavesTheOldFile) {
    QTemporaryDir dir;
    const QString path = write(dir, "image.hps", "old");
    EXPECT_THROW(writeTextFile(path,
                               [](const rs::project::TextSink& sink) {
                                   for (int i = 0; i < 100; ++i)
                                       sink(std::string(64 * 1024, 'x'));
                                   throw std::invalid_argument("refused");
                               }),
                 std::invalid_argument);
    EXPECT_EQ(readAll(path), "old");
    EXPECT_EQ(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 1);
}

TEST(TextFile, SavingIntoAMissingFolderSaysWhy) {
    QTemporaryDir dir;
    const QString path = dir.filePath("missing/p.sps");
    EXPECT_TRUE(writeTextFile(path, "x").startsWith("cannot write " + path + ": "));
}

TEST(TextFile, ReadingDropsAUtf8ByteOrderMark) {
    QTemporaryDir dir;
    const auto file = readTextFile(write(dir, "bom.scn", "\xEF\xBB\xBFset I0.0 1\n"));
    EXPECT_TRUE(file.error.isEmpty());
    EXPECT_EQ(file.text, "set I0.0 1\n");
}

TEST(TextFile, ReadingRefusesUtf16AndUtf32WithAMessage) {
    QTemporaryDir dir;
    const std::pair<QByteArray, const char*> cases[] = {
        {QByteArray("\xFF\xFEs\0e\0", 6), "UTF-16"},
        {QByteArray("\xFE\xFF\0s\0e", 6), "UTF-16"},
        {QByteArray("\xFF\xFE\0\0s\0\0\0", 8), "UTF-32"},
        {QByteArray("\0\0\xFE\xFF\0\0\0s", 8), "UTF-32"},
    };
    for (const auto& [bytes, encoding] : cases) {
        const QString path = write(dir, "wide.csv", bytes);
        const auto file = readTextFile(path);
        EXPECT_EQ(file.error, path + ": " + encoding + " text is not supported; save it as UTF-8");
        EXPECT_TRUE(file.text.empty());
    }
}

TEST(TextFile, ReadingAnEndlessDeviceStopsAtTheLimit) {
    const auto file = readTextFile(QStringLiteral("/dev/zero"));
    EXPECT_EQ(file.error, "/dev/zero: larger than 64 MB, the most Rungsmith reads from one file");
    EXPECT_TRUE(file.text.empty());
}

TEST(TextFile, ReadingTakesExactlyTheLimitAndNoMore) {
    QTemporaryDir dir;
    constexpr int kLimit = 2 * 1024 * 1024;
    const QString exact = write(dir, "exact.sps", QByteArray(kLimit, 'x'));
    EXPECT_EQ(readTextFile(exact, kLimit).text.size(), std::size_t(kLimit));
    const QString over = write(dir, "over.sps", QByteArray(kLimit + 1, 'x'));
    EXPECT_EQ(readTextFile(over, kLimit).error,
              over + ": larger than 2 MB, the most Rungsmith reads from one file");
}

TEST(TextFile, ReadingAFolderOrAMissingFileSaysWhy) {
    QTemporaryDir dir;
    EXPECT_TRUE(readTextFile(dir.path()).error.startsWith("cannot read " + dir.path() + ": "));
    const QString missing = dir.filePath("missing.sps");
    EXPECT_TRUE(readTextFile(missing).error.startsWith("cannot read " + missing + ": "));
}
