// SPDX-License-Identifier: GPL-3.0-or-later
// A check of a large project takes its memory in huge pages where the
// kernel offers them: page faults, not parsing, were a third of its time
// (docs/performance.md, "Page faults").
#include "ProgramRun.h"
#include "programs/Sanitized.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <string>

extern char** environ;

namespace {

using rs::test::writeFile;

// 16 units of 2,000 statements: 1.2 MB of text, about 25 MB of syntax tree.
QByteArray largeProject() {
    std::string text;
    for (int unit = 0; unit < 16; ++unit) {
        const std::string u = std::to_string(unit);
        text += "! id_pluto:" + u + "=000000000000\n! type_pluto:" + u + "=B46\n";
    }
    for (int unit = 0; unit < 16; ++unit) {
        const std::string u = std::to_string(unit);
        text += "! pgm_pluto:" + u + "\nS" + u + ".0_0\n";
        for (int k = 0; k < 2000; ++k)
            text += "M" + u + "." + std::to_string(k % 400) + "=I" + u + "." +
                    std::to_string(k % 16) + "*/I" + u + "." + std::to_string((k + 3) % 16) + "+M" +
                    u + "." + std::to_string((k + 7) % 400) + "  ; statement " + std::to_string(k) +
                    "\n";
    }
    return QByteArray::fromStdString(text);
}

// The minor page faults of `rungsmith-cli check FILE`, as the kernel counts them.
long checkFaults(const QString& file) {
    const QByteArray path = file.toLocal8Bit();
    char* argv[] = {const_cast<char*>(RUNGSMITH_CLI), const_cast<char*>("check"),
                    const_cast<char*>(path.constData()), nullptr};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        return -1;
    int status = 0;
    rusage usage{};
    if (wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status))
        return -1;
    return usage.ru_minflt;
}

bool hugePagesOffered() {
    QFile setting(QStringLiteral("/sys/kernel/mm/transparent_hugepage/enabled"));
    return setting.open(QIODevice::ReadOnly) && !setting.readAll().contains("[never]");
}

TEST(PageFaultCli, ALargeProjectsTreeCostsAFewHundredFaultsNotThousands) {
    if (rs::test::kSanitized)
        GTEST_SKIP() << "the sanitizer's allocator keeps its own heap";
    if (!hugePagesOffered())
        GTEST_SKIP() << "this kernel offers no transparent huge pages";
    QTemporaryDir dir;
    const long small =
        checkFaults(writeFile(dir, "small.sps", "! pgm_pluto:00\nS0.0_0\nQ0.0=I0.0\n"));
    const long large = checkFaults(writeFile(dir, "large.sps", largeProject()));
    ASSERT_GT(small, 0);
    ASSERT_GT(large, 0);
    // In 4 KB pages the tree alone would be over 6,000 faults.
    EXPECT_LT(large - small, 1000) << "small " << small << ", large " << large;
}

} // namespace
