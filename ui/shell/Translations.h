// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QLocale>

class QCoreApplication;

namespace rs::ui {

// Installs Rungsmith's translation for the locale, and Qt's own for its
// standard dialogs when the system has it. English has a translation too: it
// holds the plural forms ("1 error", "2 errors").
void installTranslations(QCoreApplication& application, const QLocale& locale = QLocale());

} // namespace rs::ui
