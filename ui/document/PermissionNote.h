// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "project/Protection.h"
#endif

#include <QString>

namespace rs::ui {

// What a page says under its title when a password-protected project is open
// without full permission; empty with full permission.
QString permissionNote(project::Permission permission);

} // namespace rs::ui
