// SPDX-License-Identifier: GPL-3.0-or-later
#include "shell/Translations.h"

#include <QApplication>
#include <QSettings>
#include <QTemporaryDir>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
    // gtest_discover_tests runs this binary at build time, where the test's
    // ENVIRONMENT property does not apply; no display is needed either way.
    qputenv("QT_QPA_PLATFORM", "offscreen");
    ::testing::InitGoogleTest(&argc, argv);
    QApplication application(argc, argv);
    // Recent files and window layout go to a scratch folder of this process: not
    // the user's, and not shared with tests that ctest runs at the same time.
    const QTemporaryDir settings;
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settings.path());
    QApplication::setOrganizationName(QStringLiteral("Rungsmith"));
    QApplication::setApplicationName(QStringLiteral("Rungsmith"));
    rs::ui::installTranslations(application, QLocale(QLocale::English, QLocale::UnitedStates));
    return RUN_ALL_TESTS();
}
