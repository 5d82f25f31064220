// SPDX-License-Identifier: GPL-3.0-or-later
#include "WindowTest.h"

#include "MessageBoxAnswerer.h"
#include "document/Autosave.h"
#include "document/ProjectDocument.h"
#include "shell/Preferences.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QSettings>
#include <QTest>

#include "QtPrinting.h"

#include <gtest/gtest.h>

#include <iostream>

namespace {

const QByteArray kCrashProject = "$name Press\n"
                                 "! id_pluto:00=000000000000\n"
                                 "! pgm_pluto:00\n"
                                 "S0.0_0\n";
const char* kDescription = "work in progress";
// What the crashing process is told through its environment (test-only).
const char* kAutosaveFolder = "RUNGSMITH_TEST_AUTOSAVE_FOLDER";
const char* kProjectFile = "RUNGSMITH_TEST_PROJECT";

using AutosaveCrashTest = WindowTest;

// The process that crashes: run by the test below, never on its own. It opens
// the project, edits it, autosaves as the timer does, and waits to be killed.
TEST(AutosaveCrashingProcess, DISABLED_EditsAutosavesAndWaits) {
    rs::ui::Autosave::setDirectory(qEnvironmentVariable(kAutosaveFolder));
    rs::ui::MainWindow window;
    ASSERT_TRUE(window.loadFile(qEnvironmentVariable(kProjectFile)).isEmpty());
    window.currentDocument()->edit(QStringLiteral("Describe"),
                                   [](rs::project::Project& p) { p.description = kDescription; });
    window.autosaveNow();
    std::cout << "autosaved" << std::endl;
    QTest::qWait(120000);
}

TEST_F(AutosaveCrashTest, AnEditSurvivesAKillAfterItsAutosave) {
    const QString path = writeFile(QStringLiteral("press.sps"), kCrashProject);
    QProcess crashing;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QString::fromLatin1(kAutosaveFolder), rs::ui::Autosave::directory());
    environment.insert(QString::fromLatin1(kProjectFile), path);
    crashing.setProcessEnvironment(environment);
    crashing.start(QCoreApplication::applicationFilePath(),
                   {QStringLiteral("--gtest_also_run_disabled_tests"),
                    QStringLiteral("--gtest_filter=AutosaveCrashingProcess.*")});
    QByteArray said;
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            crashing.waitForReadyRead(100);
            said += crashing.readAllStandardOutput();
            return said.contains("autosaved") || crashing.state() == QProcess::NotRunning;
        },
        60000));
    ASSERT_EQ(crashing.state(), QProcess::Running) << crashing.readAllStandardError().toStdString();
    crashing.kill(); // SIGKILL: no destructor, no lock released, nothing saved
    ASSERT_TRUE(crashing.waitForFinished(10000));
    EXPECT_EQ(crashing.exitStatus(), QProcess::CrashExit);
    EXPECT_EQ(readFile(path), kCrashProject);

    MessageBoxAnswerer recover(QMessageBox::Ok); // no such button: the default, Recover
    ASSERT_EQ(window.recoverAutosaved(), 1);
    rs::ui::ProjectDocument* recovered = window.currentDocument();
    ASSERT_NE(recovered, nullptr);
    EXPECT_EQ(recovered->project().description, kDescription);
    EXPECT_EQ(recovered->path(), path);
    EXPECT_TRUE(recovered->isModified());
}

TEST_F(AutosaveCrashTest, ACopyWhoseIndexIsMissingIsStillRecovered) {
    const QString path = writeFile(QStringLiteral("press.sps"), kCrashProject);
    QByteArray changed;
    {
        rs::ui::MainWindow crashed;
        ASSERT_TRUE(crashed.loadFile(path).isEmpty());
        crashed.currentDocument()->edit(QStringLiteral("Describe"), [](rs::project::Project& p) {
            p.description = kDescription;
        });
        changed = crashed.currentDocument()->fileText();
        crashed.autosaveNow();
        const QDir folder(rs::ui::Autosave::directory());
        // As if the process died between writing the copy and its index.
        for (const QString& index : folder.entryList({QStringLiteral("*.json")}, QDir::Files))
            ASSERT_TRUE(QFile::remove(folder.filePath(index)));
    }
    MessageBoxAnswerer recover(QMessageBox::Ok);
    ASSERT_EQ(window.recoverAutosaved(), 1);
    EXPECT_EQ(window.currentDocument()->fileText(), changed);
    EXPECT_TRUE(window.currentDocument()->isModified());
}

TEST(AutosavePreferences, TheIntervalIsKeptWithinItsRangeWhenRead) {
    QSettings().clear();
    const auto storedAs = [](const QVariant& minutes) {
        QSettings().setValue(QStringLiteral("preferences/autosaveMinutes"), minutes);
        return rs::ui::Preferences::load().autosaveMinutes;
    };
    EXPECT_EQ(storedAs(0), rs::ui::Preferences::kMinAutosaveMinutes);
    EXPECT_EQ(storedAs(-1), rs::ui::Preferences::kMinAutosaveMinutes);
    EXPECT_EQ(storedAs(QStringLiteral("soon")), rs::ui::Preferences::kMinAutosaveMinutes);
    EXPECT_EQ(storedAs(100000), rs::ui::Preferences::kMaxAutosaveMinutes);
    EXPECT_EQ(storedAs(5), 5);
    EXPECT_EQ(rs::ui::Preferences::kMinAutosaveMinutes, 1);
    EXPECT_EQ(rs::ui::Preferences::kMaxAutosaveMinutes, 60);
    QSettings().clear();
}

} // namespace
