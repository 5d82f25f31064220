// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "ladder/Cursor.h"
#endif

namespace rs::ui {

// What is selected on a ladder page: a place in the unit's ladder (core).
using LadderCursor = ladder::Cursor;

} // namespace rs::ui
