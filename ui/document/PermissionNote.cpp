// SPDX-License-Identifier: GPL-3.0-or-later
#include "document/PermissionNote.h"

#include <QCoreApplication>

namespace rs::ui {

QString permissionNote(project::Permission permission) {
    switch (permission) {
    case project::Permission::ReadOnly:
        return QCoreApplication::translate(
            "rs::ui::PermissionNote", "Password protected, open read only: nothing can change.");
    case project::Permission::Configure:
        return QCoreApplication::translate("rs::ui::PermissionNote",
                                           "Password protected, open with permission to "
                                           "configure: only Config Options can change, on the "
                                           "ladder.");
    case project::Permission::Full:
        break;
    }
    return {};
}

} // namespace rs::ui
