// SPDX-License-Identifier: GPL-3.0-or-later
#include "ElementIcon.h"

#include "LadderStyle.h"
#include "NetworkPainter.h"
#include "ladder/ElementVocabulary.h"

#include <QPainter>
#include <QPixmap>

namespace rs::ui {

namespace {

// The element alone on a short piece of wire, in layout units, the
// proportions of kElementIconSize.
ladder::NetworkLayout layoutOf(ElementKind kind, const QString& boxText) {
    constexpr qreal kWidth = 54;
    constexpr qreal kHeight = kWidth * kElementIconSize.height() / kElementIconSize.width();
    const qreal middle = kHeight / 2;
    const bool box = ladder::isBox(kind);
    const qreal symbolWidth = box ? 50 : 24;
    const qreal symbolHeight = box ? 28 : 26;
    ladder::ElementLayout element;
    element.kind = kind;
    const ladder::ElementKindInfo& info = ladder::infoOf(kind);
    element.shape = info.shape;
    element.mark = QString::fromUtf8(info.mark.data(), static_cast<qsizetype>(info.mark.size()));
    element.text = boxText;
    element.symbolRect =
        QRectF((kWidth - symbolWidth) / 2, middle - symbolHeight / 2, symbolWidth, symbolHeight);
    element.cell = element.symbolRect;
    ladder::NetworkLayout layout;
    layout.size = QSizeF(kWidth, kHeight);
    layout.elements.push_back(element);
    const QRectF& r = element.symbolRect;
    layout.wires.push_back({QLineF(0, middle, r.left(), middle), {}, false});
    layout.wires.push_back({QLineF(r.right(), middle, kWidth, middle), {}, false});
    return layout;
}

QIcon iconOf(const ladder::NetworkLayout& layout, const render::LadderStyle& style) {
    render::LadderStyle transparent = style;
    transparent.background = Qt::transparent;
    // Letters in the symbols large enough to read at the toolbar's scale.
    transparent.textPixelSize = 14;
    // Drawn at twice the size, so the picture stays sharp on dense screens.
    constexpr qreal kDeviceRatio = 2;
    QPixmap pixmap(kElementIconSize * kDeviceRatio);
    pixmap.setDevicePixelRatio(kDeviceRatio);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    const qreal scale = kElementIconSize.width() / layout.size.width();
    painter.scale(scale, scale);
    render::paintNetwork(painter, layout, transparent);
    painter.end();
    return QIcon(pixmap);
}

} // namespace

QIcon elementIcon(ElementKind kind, const render::LadderStyle& style) {
    const std::string_view word = ladder::infoOf(kind).boxWord;
    return iconOf(
        layoutOf(kind, QString::fromLatin1(word.data(), static_cast<qsizetype>(word.size()))),
        style);
}

QIcon blockIcon(const render::LadderStyle& style) {
    // Any box kind draws a plain box with the text given.
    return iconOf(layoutOf(ElementKind::OnDelayTimer, QStringLiteral("F")), style);
}

} // namespace rs::ui
