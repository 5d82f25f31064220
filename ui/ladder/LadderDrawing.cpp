// SPDX-License-Identifier: GPL-3.0-or-later
#include "LadderDrawing.h"

#include <QPalette>

namespace rs::ui {

LadderDrawing drawingFor(const QPalette& palette, const LadderColours& chosen, bool live) {
    LadderDrawing drawing;
    render::LadderStyle& style = drawing.style;
    style.background = palette.color(QPalette::Base);
    style.ink = palette.color(QPalette::Text);
    const bool dark = style.background.lightness() < 128;
    if (dark) {
        style.powered = QColor(70, 210, 110);
        style.poweredFill = QColor(30, 80, 45);
        style.closedFill = style.powered;
        style.nameInk = QColor(140, 180, 255);
        style.addressInk = QColor(190, 190, 190);
        style.commentInk = QColor(170, 170, 170);
    }
    auto choose = [](QColor& colour, const QColor& chosen) {
        if (chosen.isValid())
            colour = chosen;
    };
    choose(style.background, chosen.background);
    style.body = chosen.componentBody; // invalid: as the background
    choose(style.ink, live ? chosen.linesOff : chosen.lines);
    choose(style.powered, chosen.linesOn);
    choose(style.closedFill, chosen.linesOn);
    style.closedInk = style.background;
    drawing.selection = palette.color(QPalette::Highlight);
    choose(drawing.selection, chosen.focusedBackground);
    drawing.markedNetwork = palette.color(QPalette::Highlight);
    drawing.markedNetwork.setAlpha(60);
    drawing.problem = dark ? QColor(255, 90, 90) : QColor(210, 0, 0);
    drawing.editing = dark ? QColor(255, 170, 60) : QColor(220, 120, 0);
    drawing.explained = dark ? QColor(255, 120, 220) : QColor(190, 0, 140);
    // Neither green nor red: those say power and problems.
    drawing.changedSinceValidation = dark ? QColor(255, 190, 60) : QColor(215, 140, 0);
    drawing.addedSinceValidation = dark ? QColor(100, 170, 255) : QColor(30, 110, 220);
    return drawing;
}

} // namespace rs::ui
