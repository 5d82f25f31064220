// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "shell/Preferences.h"

namespace rs::ui {

// Sets the application's palette for the theme: the style's own for System
// and Light (on a desktop that is dark, System follows it), a dark palette
// for Dark.
void applyTheme(Preferences::Theme theme);

} // namespace rs::ui
