// SPDX-License-Identifier: GPL-3.0-or-later
#include "shell/Translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QTranslator>

namespace rs::ui {

void installTranslations(QCoreApplication& application, const QLocale& locale) {
    // "qt" is Qt 6's catalogue of catalogues (qt_de loads qtbase_de and the
    // rest) or, for Swedish on Debian 12, Qt 4's single catalogue, which still
    // holds the file dialog's and the text fields' strings.
    auto* qt = new QTranslator(&application);
    if (qt->load(locale, QStringLiteral("qt"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt);
    else
        delete qt;

    // qt_add_translations embeds the compiled catalogues under this prefix.
    const QString directory = QStringLiteral(":/i18n");
    auto* own = new QTranslator(&application);
    if (own->load(locale, QStringLiteral("rungsmith"), QStringLiteral("_"), directory) ||
        own->load(QStringLiteral("rungsmith_en"), directory))
        QCoreApplication::installTranslator(own);
    else
        delete own;
}

} // namespace rs::ui
