// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QIcon>

namespace rs::ui {

// One of the IDE's own icons, resources/icons/NAME.svg.
QIcon namedIcon(const char* name);

} // namespace rs::ui
