// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "project/UnitSettings.h"

#include <QString>

namespace rs::ui {

// How the window names a unit everywhere: "Pluto 3 — B46".
QString unitCaption(const project::UnitSettings& unit);
QString unitCaption(const project::Project& project, int station);

} // namespace rs::ui
