// SPDX-License-Identifier: GPL-3.0-or-later
#include "LadderStyle.h"

namespace rs::render {

QPen LadderStyle::wirePen(bool conducting) const {
    QPen pen(conducting ? powered : ink, conducting ? poweredLineWidth : lineWidth);
    pen.setCapStyle(Qt::FlatCap);
    pen.setJoinStyle(Qt::MiterJoin);
    return pen;
}

QPen LadderStyle::railPen(bool conducting) const {
    QPen pen(conducting ? powered : ink, conducting ? poweredRailWidth : railWidth);
    pen.setCapStyle(Qt::FlatCap);
    return pen;
}

QFont LadderStyle::font(int pixelSize, bool bold, bool italic) const {
    QFont font(fontFamily);
    font.setStyleHint(QFont::SansSerif);
    font.setPixelSize(pixelSize);
    font.setBold(bold);
    font.setItalic(italic);
    return font;
}

} // namespace rs::render
