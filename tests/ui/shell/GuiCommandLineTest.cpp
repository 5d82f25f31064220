// SPDX-License-Identifier: GPL-3.0-or-later
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>

#include "QtPrinting.h"

#include <gtest/gtest.h>

namespace {

struct GuiRun {
    int exitCode = -1;
    QString out;
    QString err;
};

// Runs the IDE binary without a display, with settings in a scratch folder.
GuiRun gui(const QStringList& arguments) {
    static QTemporaryDir home;
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    environment.insert(QStringLiteral("XDG_CONFIG_HOME"), home.path());
    process.setProcessEnvironment(environment);
    process.start(QStringLiteral(RUNGSMITH_GUI), arguments);
    EXPECT_TRUE(process.waitForFinished(60000));
    return {process.exitCode(), QString::fromUtf8(process.readAllStandardOutput()),
            QString::fromUtf8(process.readAllStandardError())};
}

const QString kCommandLineMuting = QStringLiteral(RUNGSMITH_TEST_DATA "/manual/manual_muting.sps");

class GuiCommandLine : public ::testing::Test {
protected:
    QString out(const QString& name) const { return directory.filePath(name); }
    QTemporaryDir directory;
};

TEST_F(GuiCommandLine, ScreenshotOfTheExampleIsAWindowSizedPicture) {
    const GuiRun run = gui({QStringLiteral("--screenshot"), out("shot.png")});
    EXPECT_EQ(run.exitCode, 0) << run.err.toStdString();
    const QImage picture(out("shot.png"));
    ASSERT_FALSE(picture.isNull());
    EXPECT_EQ(picture.size(), QSize(1280, 800));
}

TEST_F(GuiCommandLine, ScreenshotOfAFileOnItsTextPage) {
    const GuiRun run = gui({kCommandLineMuting, QStringLiteral("--screenshot"), out("text.png"),
                            QStringLiteral("--page"), QStringLiteral("text:0")});
    EXPECT_EQ(run.exitCode, 0) << run.err.toStdString();
    EXPECT_FALSE(QImage(out("text.png")).isNull());
}

TEST_F(GuiCommandLine, ScreenshotsOfEveryPageOfAUnit) {
    for (const QString& page :
         {QStringLiteral("io:0"), QStringLiteral("variables:0"), QStringLiteral("unit:0"),
          QStringLiteral("text:0"), QStringLiteral("project")}) {
        const QString picture =
            out(QString(page).replace(QLatin1Char(':'), QLatin1Char('-')) + QStringLiteral(".png"));
        const GuiRun run = gui({kCommandLineMuting, QStringLiteral("--screenshot"), picture,
                                QStringLiteral("--page"), page, QStringLiteral("--theme"),
                                QStringLiteral("dark")});
        EXPECT_EQ(run.exitCode, 0) << page.toStdString() << ": " << run.err.toStdString();
        EXPECT_EQ(QImage(picture).size(), QSize(1280, 800)) << page.toStdString();
    }
}

TEST_F(GuiCommandLine, ScreenshotsOfASequence) {
    // The muting example has sequence 1 in unit 0, written S0.1 in the language.
    for (const QString& page : {QStringLiteral("ladder:0.1"), QStringLiteral("text:0.1")}) {
        const GuiRun run = gui({kCommandLineMuting, QStringLiteral("--screenshot"),
                                out("sequence.png"), QStringLiteral("--page"), page});
        EXPECT_EQ(run.exitCode, 0) << page.toStdString() << ": " << run.err.toStdString();
    }
    GuiRun run = gui({kCommandLineMuting, QStringLiteral("--screenshot"), out("none.png"),
                      QStringLiteral("--page"), QStringLiteral("ladder:0.5")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.err.contains(QStringLiteral("no sequence 5 in unit 0")))
        << run.err.toStdString();
    run = gui({kCommandLineMuting, QStringLiteral("--screenshot"), out("io.png"),
               QStringLiteral("--page"), QStringLiteral("io:0.1")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.err.contains(QStringLiteral("unknown page 'io:0.1'"))) << run.err.toStdString();
}

TEST_F(GuiCommandLine, AnUnknownThemeIsExitTwo) {
    const GuiRun run = gui({QStringLiteral("--screenshot"), out("a.png"), QStringLiteral("--theme"),
                            QStringLiteral("purple")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.err.contains(QStringLiteral("purple"))) << run.err.toStdString();
}

TEST_F(GuiCommandLine, AnUnreadableFileIsExitTwoAndNamed) {
    const QString missing = out("missing.sps");
    const GuiRun run = gui({missing, QStringLiteral("--screenshot"), out("shot.png")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.err.contains(missing)) << run.err.toStdString();
    EXPECT_FALSE(QFile::exists(out("shot.png")));
}

TEST_F(GuiCommandLine, AnUnwritablePictureIsExitTwo) {
    const QString unwritable = out("no-such-folder/shot.png");
    const GuiRun run = gui({QStringLiteral("--screenshot"), unwritable});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.err.contains(unwritable)) << run.err.toStdString();
}

TEST_F(GuiCommandLine, UnknownPagesAndUnitsAreExitTwo) {
    GuiRun run = gui({QStringLiteral("--screenshot"), out("a.png"), QStringLiteral("--page"),
                      QStringLiteral("ladder-ish:0")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.err.contains(QStringLiteral("ladder-ish:0"))) << run.err.toStdString();

    run = gui({kCommandLineMuting, QStringLiteral("--screenshot"), out("b.png"),
               QStringLiteral("--page"), QStringLiteral("text:7")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.err.contains(QStringLiteral("no unit 7"))) << run.err.toStdString();
    run = gui({kCommandLineMuting, QStringLiteral("--screenshot"), out("c.png"),
               QStringLiteral("--page"), QStringLiteral("io:31")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.err.contains(QStringLiteral("no unit 31"))) << run.err.toStdString();
}

TEST_F(GuiCommandLine, UnknownOptionsAreExitTwo) {
    const GuiRun run = gui({QStringLiteral("--no-such-option")});
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_TRUE(run.err.contains(QStringLiteral("no-such-option"))) << run.err.toStdString();
}

TEST_F(GuiCommandLine, VersionIsPrinted) {
    const GuiRun run = gui({QStringLiteral("--version")});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_TRUE(run.out.contains(QStringLiteral(RUNGSMITH_VERSION))) << run.out.toStdString();
}

} // namespace
