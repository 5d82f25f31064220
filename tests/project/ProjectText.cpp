// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectText.h"

#include "project/ProjectFile.h"

rs::project::Project projectFrom(std::string_view text) {
    auto read = rs::project::readProject(text);
    EXPECT_TRUE(read.ok()) << (read.diagnostics.empty() ? "" : read.diagnostics.front().message);
    return std::move(read.project);
}

::testing::AssertionResult isStable(const rs::project::Project& project) {
    const std::string text = rs::project::writeProject(project);
    auto read = rs::project::readProject(text);
    if (!read.ok())
        return ::testing::AssertionFailure()
               << "the written text has errors: line " << read.diagnostics.front().line << ": "
               << read.diagnostics.front().message << "\n"
               << text;
    if (!(read.project == project))
        return ::testing::AssertionFailure() << "reading the written text gives another project:\n"
                                             << text;
    if (rs::project::writeProject(read.project) != text)
        return ::testing::AssertionFailure() << "writing it again gives other bytes:\n" << text;
    return ::testing::AssertionSuccess();
}

std::string textOf(const rs::project::Project& project) {
    return rs::project::writeProject(project);
}
