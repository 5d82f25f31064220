// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QLocale>

class QCoreApplication;

namespace rs::ui {

// Installs Rungsmith's translation for the locale, and Qt's own for its
// standard dialogs when the system has it (package qt6-translations-l10n);
// Rungsmith's catalogues also hold the standard buttons' texts, which
// Debian's Swedish catalogue of Qt lacks (QtStandardStrings.cpp). English has a translation too: it
// holds the plural forms ("1 error", "2 errors").
void installTranslations(QCoreApplication& application, const QLocale& locale = QLocale());

} // namespace rs::ui
