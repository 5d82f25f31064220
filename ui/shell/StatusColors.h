// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QColor>
#include <QPalette>

class QWidget;

namespace rs::ui {

// Colours for what the palette has no role for, readable on light and dark
// palettes alike: text that reports an error, and the red of the [R] mark;
// text that reports success (a scenario passed, a property proved); text that
// reports neither (a property not proved, nor broken).
bool isDark(const QPalette& palette);
QColor errorTextColor(const QPalette& palette);
QColor passTextColor(const QPalette& palette);
QColor undecidedTextColor(const QPalette& palette);

// Shows the widget's text in the error colour.
void markAsError(QWidget* widget);

} // namespace rs::ui
