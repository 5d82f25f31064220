// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QColor>
#include <QFont>
#include <QPen>

namespace rs::render {

// Colours, line weights and fonts of the drawing. Conducting wires and
// elements differ from the others in colour and in line weight, and an
// element's own state (a closed contact, a true comparison, an output whose
// variable is 1) is a filled symbol, so both read without colour too (in
// print, in greyscale, for colour-blind users).
struct LadderStyle {
    QColor background{255, 255, 255};
    QColor ink{32, 32, 32};            // wires, rails, symbols
    QColor powered{0, 150, 60};        // conducting wires and elements
    QColor poweredFill{200, 240, 210}; // inside a block pin's contact whose bit is 1
    QColor closedFill{0, 150, 60};     // inside a closed contact, a true box, an output that is 1
    QColor closedInk{255, 255, 255};   // a letter or slash on closedFill
    QColor body;                       // inside an open contact, a box, a coil; invalid: background
    QColor nameInk{20, 40, 120};       // symbolic names
    QColor addressInk{70, 70, 70};     // addresses, presets
    QColor commentInk{90, 90, 90};     // comments among and beside the rungs
    qreal lineWidth = 1.5;
    qreal poweredLineWidth = 4;
    qreal railWidth = 3;
    qreal poweredRailWidth = 5;
    QString fontFamily = QStringLiteral("DejaVu Sans");
    int labelPixelSize = 11; // names, addresses, comments
    int textPixelSize = 12;  // inside boxes and coils
    int titlePixelSize = 13;

    QPen wirePen(bool conducting) const;
    QPen railPen(bool conducting) const;
    QFont font(int pixelSize, bool bold = false, bool italic = false) const;
};

} // namespace rs::render
