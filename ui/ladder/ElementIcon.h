// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "ElementKind.h"

#include <QIcon>

namespace rs::render {
struct LadderStyle;
}

namespace rs::ui {

// The size of the pictures, in the toolbar's pixels: wide enough for a box's
// text ("TON", ">=") to stay legible.
inline constexpr QSize kElementIconSize{36, 22};

// A toolbar picture of an element kind, drawn by the ladder renderer itself,
// so a button shows the symbol exactly as the page draws it, in the theme's
// colours; and greyed when the action is disabled.
QIcon elementIcon(ElementKind kind, const render::LadderStyle& style);
// The picture of a function block: a box with "F", as the manual's button has.
QIcon blockIcon(const render::LadderStyle& style);

} // namespace rs::ui
