#include "Translations.h"

#include <QApplication>
#include <QStandardPaths>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
    // gtest_discover_tests runs this binary at build time, where the test's
    // ENVIRONMENT property does not apply; no display is needed either way.
    qputenv("QT_QPA_PLATFORM", "offscreen");
    // Recent files and window layout go to a scratch settings folder, not the user's.
    QStandardPaths::setTestModeEnabled(true);
    ::testing::InitGoogleTest(&argc, argv);
    QApplication application(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("Rungsmith"));
    QApplication::setApplicationName(QStringLiteral("Rungsmith"));
    rs::ui::installTranslations(application, QLocale(QLocale::English, QLocale::UnitedStates));
    return RUN_ALL_TESTS();
}
