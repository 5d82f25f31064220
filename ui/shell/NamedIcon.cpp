// SPDX-License-Identifier: GPL-3.0-or-later
#include "shell/NamedIcon.h"

#include <QString>

namespace rs::ui {

QIcon namedIcon(const char* name) {
    return QIcon(QStringLiteral(":/icons/%1.svg").arg(QLatin1String(name)));
}

} // namespace rs::ui
