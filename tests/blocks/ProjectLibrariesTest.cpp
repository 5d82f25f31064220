// SPDX-License-Identifier: GPL-3.0-or-later
#include "blocks/ProjectInstances.h"
#include "project/ProjectFile.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace rs;

namespace {

void writeLibrary(const QString& path, const std::string& name, const std::string& block) {
    QDir().mkpath(QFileInfo(path).path());
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    const std::string text = "rungsmith-library 1\nlibrary " + name + "\nversion 1\nblock " +
                             block +
                             "\nkind macro\nversion 1\ndescription en x\n"
                             "pin In in bit primary\npin Out out bit primary\n"
                             "body {Out} = {In}\n";
    file.write(text.c_str());
}

std::vector<std::string> names(const blocks::LibrarySet& set) {
    std::vector<std::string> result;
    for (const auto& loaded : set.libraries)
        result.push_back(loaded.library.name);
    return result;
}

// A program folder with two standard libraries and a project folder with one
// user library.
class ProjectLibraries : public ::testing::Test {
protected:
    void SetUp() override {
        writeLibrary(root.filePath("bin/libraries/a.rslib"), "Alpha", "A");
        writeLibrary(root.filePath("bin/libraries/b.rslib"), "Beta", "B");
        writeLibrary(root.filePath("project/mine.rslib"), "Mine", "M");
        writeLibrary(root.filePath("project/sub/other.rslib"), "Other", "O");
    }
    blocks::LibraryPlaces places() {
        return {root.filePath("bin"), root.filePath("project/p.sps"), {}};
    }
    QTemporaryDir root;
};

TEST_F(ProjectLibraries, AProjectThatNamesNoneSeesEveryLibraryFound) {
    const auto set = blocks::librariesFor(places(), {});
    const std::vector<std::string> expected{"Alpha", "Beta", "Mine"};
    EXPECT_EQ(names(set), expected);
    EXPECT_TRUE(set.problems.empty());
}

TEST_F(ProjectLibraries, AProjectThatNamesItsLibrariesSeesThoseOnly) {
    const auto set = blocks::librariesFor(places(), {"Beta", "sub/other.rslib"});
    const std::vector<std::string> expected{"Beta", "Other"};
    EXPECT_EQ(names(set), expected);
    EXPECT_TRUE(set.problems.empty());
}

TEST_F(ProjectLibraries, ANamedLibraryThatIsNotInstalledIsAWarning) {
    const auto set = blocks::librariesFor(places(), {"Alpha", "Gamma"});
    const std::vector<std::string> expected{"Alpha"};
    EXPECT_EQ(names(set), expected);
    ASSERT_EQ(set.problems.size(), 1u);
    ASSERT_EQ(set.problems[0].diagnostics.size(), 1u);
    EXPECT_EQ(set.problems[0].diagnostics[0].severity, lang::Severity::Warning);
    EXPECT_EQ(set.problems[0].diagnostics[0].message,
              "the project uses the library 'Gamma', which is not installed");
}

TEST_F(ProjectLibraries, TheRecordKeepsTheListAndReadingUsesIt) {
    const std::string text = ";@project library=\"Beta\" library=\"mine.rslib\"\n"
                             "! id_pluto:00=000000000000\n"
                             "! pgm_pluto:00\n"
                             "S0.0_0\n"
                             ";@block M In=\"I0.0\" Out=\"Q0.2\"\n;@end\n"
                             ";@block A In=\"I0.1\" Out=\"Q0.3\"\n;@end\n";
    const auto read = blocks::readProjectWithInstances(text, places());
    const std::vector<std::string> libraries{"Beta", "mine.rslib"};
    EXPECT_EQ(read.read.project.libraries, libraries);
    ASSERT_EQ(read.read.diagnostics.size(), 1u);
    EXPECT_EQ(read.read.diagnostics[0].message, "unknown block 'A'") << "Alpha is not used";
    const std::string written = project::writeProject(read.read.project);
    EXPECT_EQ(written.rfind(";@project library=\"Beta\" library=\"mine.rslib\"\n", 0), 0u)
        << written;
    EXPECT_NE(written.find("lib=\"Mine\" version=\"1\"\nQ0.2 = I0.0\n"), std::string::npos)
        << written;
}

// A broken standard library holds up only a project that uses a block: one
// without instances is read without reading the standard libraries, while
// its own libraries are still read and their problems reported.
TEST_F(ProjectLibraries, OnlyAProjectWithInstancesReadsTheStandardLibraries) {
    QFile broken(root.filePath("bin/libraries/broken.rslib"));
    ASSERT_TRUE(broken.open(QIODevice::WriteOnly));
    broken.write("rungsmith-library 1\nlibrary Broken\nnonsense\n");
    broken.close();
    const auto problemPaths = [](const blocks::ProjectWithInstances& read) {
        std::vector<std::string> paths;
        for (const auto& problem : read.libraryProblems)
            paths.push_back(QFileInfo(problem.path).fileName().toStdString());
        return paths;
    };
    const std::string plain = "! pgm_pluto:00\nS0.0_0\nQ0.2 = I0.0\n";
    const auto withoutInstances = blocks::readProjectWithInstances(plain, places());
    EXPECT_TRUE(withoutInstances.read.ok());
    EXPECT_TRUE(problemPaths(withoutInstances).empty());

    const std::string withInstance = plain + ";@block A In=\"I0.1\" Out=\"Q0.3\"\n;@end\n";
    const auto read = blocks::readProjectWithInstances(withInstance, places());
    EXPECT_EQ(problemPaths(read), std::vector<std::string>{"broken.rslib"});
    EXPECT_TRUE(read.expanded) << "Alpha's A is expanded";

    // The user's own broken library is reported either way.
    QFile mine(root.filePath("project/mine.rslib"));
    ASSERT_TRUE(mine.open(QIODevice::WriteOnly | QIODevice::Truncate));
    mine.write("rungsmith-library 1\nlibrary Mine\nnonsense\n");
    mine.close();
    EXPECT_EQ(problemPaths(blocks::readProjectWithInstances(plain, places())),
              std::vector<std::string>{"mine.rslib"});
}

} // namespace
