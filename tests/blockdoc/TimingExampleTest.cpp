// SPDX-License-Identifier: GPL-3.0-or-later
#include "blockdoc/TimingExample.h"
#include "blocks/LibraryReader.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace rs::blockdoc {
namespace {

const char* const kLibrary = R"(rungsmith-library 1
library Demo
version 1.0
description en Blocks for the timing example tests.

block Latch
    kind macro
    version 1.0
    description en Out is set by Set and reset by Reset.
    pin Set in bit primary
    pin Reset in bit secondary default=0
    pin Out out bit primary
    private held memory
    body S({#held}) = {Set}
    body R({#held}) = {Reset}
    body {Out} = {#held}
)";

const char* const kProject = R"(! id_pluto:00=000000000000
! type_pluto:00=A20,is3
! pgm_pluto:00
! I0.0=SetButton
! I0.1=ResetButton
! M0.0=Lamp
S0.0_0
;@block Latch Set="SetButton" Reset="ResetButton" Out="Lamp"
;@end
)";

const char* const kScenario = R"(; Set at 100 ms, reset at 300 ms.
run 100ms
set SetButton 1
scans 1
expect Lamp 1
set SetButton 0
run 200ms
expect Lamp 1
set ResetButton 1
scans 1
expect Lamp 0
)";

void write(const QString& path, const std::string& text) {
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(text.data(), static_cast<qint64>(text.size()));
}

class TimingExampleTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(m_folder.isValid());
        const blocks::LibraryReadResult read = blocks::readLibrary(kLibrary);
        ASSERT_TRUE(read.ok());
        m_library = {read.library, m_folder.filePath(QStringLiteral("Demo.rslib")),
                     blocks::LibraryOrigin::User};
        write(m_library.path, kLibrary);
    }
    const blocks::BlockDefinition& latch() const { return *m_library.library.findBlock("Latch"); }
    void writeExample(const std::string& project, const std::string& scenario) {
        const TimingExampleFiles files = timingExampleFiles(m_library, latch());
        write(files.project, project);
        write(files.scenario, scenario);
    }

    QTemporaryDir m_folder;
    blocks::LoadedLibrary m_library;
};

TEST_F(TimingExampleTest, LiesBesideTheLibraryInAFolderNamedAsIt) {
    const TimingExampleFiles files = timingExampleFiles(m_library, latch());
    EXPECT_EQ(files.project, m_folder.filePath(QStringLiteral("Demo/Latch.sps")));
    EXPECT_EQ(files.scenario, m_folder.filePath(QStringLiteral("Demo/Latch.scn")));
}

TEST_F(TimingExampleTest, RecordsWhatTheInstancesPinsDid) {
    writeExample(kProject, kScenario);
    const TimingExample example = runTimingExample(m_library, latch());
    ASSERT_TRUE(example.ran()) << example.problem;
    EXPECT_EQ(example.passed, 3);
    EXPECT_EQ(example.failed, 0);
    const std::vector<std::string> labels{"Set", "Reset", "Out"};
    EXPECT_EQ(example.labels, labels);
    const auto& traces = example.recording.traces();
    ASSERT_EQ(traces.size(), 3u);
    // Out: 0 from power on, 1 once Set was seen, 0 once Reset was.
    const auto& out = traces[2].changes;
    ASSERT_EQ(out.size(), 3u);
    EXPECT_EQ(out[0].value, 0);
    EXPECT_EQ(out[1].value, 1);
    EXPECT_EQ(out[2].value, 0);
    EXPECT_GE(out[1].timeMs, 100);
    EXPECT_LE(out[1].timeMs, 120);
    EXPECT_GE(out[2].timeMs - out[1].timeMs, 200);
    EXPECT_GE(example.recording.endMs(), out[2].timeMs);
}

TEST_F(TimingExampleTest, CountsExpectationsThatFail) {
    std::string scenario = kScenario;
    scenario.replace(scenario.rfind("expect Lamp 0"), 13, "expect Lamp 1");
    writeExample(kProject, scenario);
    const TimingExample example = runTimingExample(m_library, latch());
    ASSERT_TRUE(example.ran()) << example.problem;
    EXPECT_EQ(example.failed, 1);
}

TEST_F(TimingExampleTest, SaysWhyThereIsNoDiagram) {
    TimingExample missing = runTimingExample(m_library, latch());
    EXPECT_FALSE(missing.ran());
    EXPECT_NE(missing.problem.find("Latch.sps: no such file"), std::string::npos)
        << missing.problem;

    std::string project = kProject;
    project.replace(project.find("Out=\"Lamp\""), 10, "Out=\"Nowhere\"");
    writeExample(project, kScenario);
    const TimingExample badProject = runTimingExample(m_library, latch());
    EXPECT_FALSE(badProject.ran());
    EXPECT_NE(badProject.problem.find("Latch.sps:8:"), std::string::npos) << badProject.problem;

    writeExample(kProject, "set NoSuchName 1\nexpect Lamp 0\n");
    const TimingExample badScenario = runTimingExample(m_library, latch());
    EXPECT_FALSE(badScenario.ran());
    EXPECT_NE(badScenario.problem.find("Latch.scn:1:"), std::string::npos) << badScenario.problem;
}

} // namespace
} // namespace rs::blockdoc
