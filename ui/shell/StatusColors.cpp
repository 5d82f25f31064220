// SPDX-License-Identifier: GPL-3.0-or-later
#include "shell/StatusColors.h"

#include <QWidget>

namespace rs::ui {

bool isDark(const QPalette& palette) {
    return palette.color(QPalette::Window).lightness() < 128;
}

QColor errorTextColor(const QPalette& palette) {
    return isDark(palette) ? QColor(0xff7b72) : QColor(0xcf222e);
}

QColor passTextColor(const QPalette& palette) {
    return isDark(palette) ? QColor(80, 220, 80) : QColor(0, 128, 0);
}

QColor undecidedTextColor(const QPalette& palette) {
    return isDark(palette) ? QColor(0xe3b341) : QColor(0x9a6700);
}

void markAsError(QWidget* widget) {
    QPalette palette = widget->palette();
    palette.setColor(QPalette::WindowText, errorTextColor(palette));
    palette.setColor(QPalette::Text, errorTextColor(palette));
    widget->setPalette(palette);
}

} // namespace rs::ui
