// SPDX-License-Identifier: GPL-3.0-or-later
#include "shell/UnitCaption.h"

#include <QCoreApplication>

namespace rs::ui {

QString unitCaption(const project::UnitSettings& unit) {
    return QCoreApplication::translate("UnitCaption", "Pluto %1 — %2")
        .arg(unit.station)
        .arg(QString::fromUtf8(
            target::unitTypeInfo(unit.type).display.data(),
            static_cast<qsizetype>(target::unitTypeInfo(unit.type).display.size())));
}

QString unitCaption(const project::Project& project, int station) {
    if (const auto unit = project::unitSettings(project, station))
        return unitCaption(*unit);
    return QCoreApplication::translate("UnitCaption", "Pluto %1").arg(station);
}

} // namespace rs::ui
