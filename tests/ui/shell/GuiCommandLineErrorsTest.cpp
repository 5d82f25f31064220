// SPDX-License-Identifier: GPL-3.0-or-later
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>

#include "QtPrinting.h"

#include <gtest/gtest.h>

// What the IDE's command line says, and leaves, when its scenario, project or
// picture cannot be used: a message, a non-zero exit, no picture.

namespace {

struct GuiErrorsRun {
    int exitCode = -1;
    QString err;
};

const QString kErrorsMuting = QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps");

class GuiCommandLineErrors : public ::testing::Test {
protected:
    GuiErrorsRun gui(const QStringList& arguments) {
        QProcess process;
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        environment.insert(QStringLiteral("XDG_CONFIG_HOME"), directory.path());
        environment.insert(QStringLiteral("XDG_DATA_HOME"), directory.path());
        process.setProcessEnvironment(environment);
        process.start(QStringLiteral(RUNGSMITH_GUI), arguments);
        EXPECT_TRUE(process.waitForFinished(60000));
        return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1,
                QString::fromUtf8(process.readAllStandardError())};
    }
    QString file(const QString& name, const QByteArray& bytes) {
        QFile out(directory.filePath(name));
        EXPECT_TRUE(out.open(QIODevice::WriteOnly));
        out.write(bytes);
        return out.fileName();
    }
    QString out(const QString& name) const { return directory.filePath(name); }
    QTemporaryDir directory;
};

TEST_F(GuiCommandLineErrors, AScenarioWithSyntaxErrorsIsReportedAndNothingDrawn) {
    const QString scenario = file(QStringLiteral("bad.scn"), "set I0.12 1\nrun soon\n");
    const GuiErrorsRun run = gui({kErrorsMuting, QStringLiteral("--simulate"), scenario,
                                  QStringLiteral("--screenshot"), out(QStringLiteral("shot.png"))});
    EXPECT_EQ(run.exitCode, 1) << run.err.toStdString();
    EXPECT_TRUE(run.err.contains(scenario + QStringLiteral(":2:5: error: ")))
        << run.err.toStdString();
    EXPECT_FALSE(QFile::exists(out(QStringLiteral("shot.png"))));
}

TEST_F(GuiCommandLineErrors, AnUnreadableScenarioIsAUsageError) {
    const GuiErrorsRun run = gui({kErrorsMuting, QStringLiteral("--simulate"), directory.path(),
                                  QStringLiteral("--screenshot"), out(QStringLiteral("shot.png"))});
    EXPECT_EQ(run.exitCode, 2) << run.err.toStdString();
    EXPECT_FALSE(run.err.isEmpty());
    EXPECT_FALSE(QFile::exists(out(QStringLiteral("shot.png"))));
}

TEST_F(GuiCommandLineErrors, AProjectThatDoesNotReadIsAUsageError) {
    const GuiErrorsRun run = gui({out(QStringLiteral("missing.sps")),
                                  QStringLiteral("--screenshot"), out(QStringLiteral("shot.png"))});
    EXPECT_EQ(run.exitCode, 2) << run.err.toStdString();
    EXPECT_TRUE(run.err.contains(QStringLiteral("missing.sps"))) << run.err.toStdString();
    EXPECT_FALSE(QFile::exists(out(QStringLiteral("shot.png"))));
}

TEST_F(GuiCommandLineErrors, APl110ProgramOpensInItsOwnWindowAndRefusesAPlutoPage) {
    const QString program = file(QStringLiteral("station.sps"), "$target PL110\nMAIN\nQ1 = I1\n");
    GuiErrorsRun run =
        gui({program, QStringLiteral("--screenshot"), out(QStringLiteral("shot.png"))});
    EXPECT_EQ(run.exitCode, 0) << run.err.toStdString();
    EXPECT_TRUE(QFile::exists(out(QStringLiteral("shot.png"))));
    // Not read as a broken Pluto project: no wall of Pluto errors.
    EXPECT_FALSE(run.err.contains(QStringLiteral("error"))) << run.err.toStdString();

    run = gui({program, QStringLiteral("--page"), QStringLiteral("io:1"),
               QStringLiteral("--screenshot"), out(QStringLiteral("io.png"))});
    EXPECT_EQ(run.exitCode, 2) << run.err.toStdString();
    EXPECT_TRUE(run.err.contains(QStringLiteral("PL110 program"))) << run.err.toStdString();
    EXPECT_FALSE(QFile::exists(out(QStringLiteral("io.png"))));

    run = gui({program, QStringLiteral("--page"), QStringLiteral("ladder:7"),
               QStringLiteral("--screenshot"), out(QStringLiteral("rung.png"))});
    EXPECT_EQ(run.exitCode, 2) << run.err.toStdString();
    EXPECT_TRUE(run.err.contains(QStringLiteral("has no rung 7"))) << run.err.toStdString();
    EXPECT_FALSE(QFile::exists(out(QStringLiteral("rung.png"))));
}

TEST_F(GuiCommandLineErrors, APictureThatCannotBeWrittenIsSaidAndLeavesNoFile) {
    // The destination's folder does not exist.
    const QString nowhere = out(QStringLiteral("no/such/folder/shot.png"));
    GuiErrorsRun run = gui({kErrorsMuting, QStringLiteral("--screenshot"), nowhere});
    EXPECT_EQ(run.exitCode, 2) << run.err.toStdString();
    EXPECT_TRUE(run.err.contains(nowhere)) << run.err.toStdString();
    // The destination is a folder: it stays one.
    QDir(directory.path()).mkdir(QStringLiteral("taken.png"));
    run = gui({kErrorsMuting, QStringLiteral("--screenshot"), out(QStringLiteral("taken.png"))});
    EXPECT_EQ(run.exitCode, 2) << run.err.toStdString();
    EXPECT_TRUE(QFileInfo(out(QStringLiteral("taken.png"))).isDir());
    EXPECT_TRUE(QDir(directory.path()).entryList({QStringLiteral("*.png*")}, QDir::Files).isEmpty())
        << QDir(directory.path()).entryList().join(QLatin1Char(' ')).toStdString();
}

} // namespace
