// SPDX-License-Identifier: GPL-3.0-or-later
#include "NetworkPicture.h"

#include "NetworkPainter.h"
#include "project/SaveFileCommit.h"

#include <QBuffer>
#include <QPainter>
#include <QSaveFile>
#include <QSvgGenerator>

#include <cmath>

namespace rs::render {

namespace {

constexpr qreal kPngScale = 2;

bool hasSuffix(const QString& path, const char* suffix) {
    return path.endsWith(QLatin1String(suffix), Qt::CaseInsensitive);
}

} // namespace

QImage networkImage(const ladder::NetworkLayout& layout, const LadderStyle& style,
                    const PowerSnapshot* power, qreal scale) {
    const QSize pixels(static_cast<int>(std::ceil(layout.size.width() * scale)),
                       static_cast<int>(std::ceil(layout.size.height() * scale)));
    QImage image(pixels, QImage::Format_ARGB32_Premultiplied);
    image.fill(style.background);
    QPainter painter(&image);
    painter.scale(scale, scale);
    paintNetwork(painter, layout, style, power);
    return image;
}

QByteArray networkSvg(const ladder::NetworkLayout& layout, const LadderStyle& style,
                      const PowerSnapshot* power, const QString& title) {
    QBuffer buffer;
    QSvgGenerator generator;
    generator.setOutputDevice(&buffer);
    const QSize size(static_cast<int>(std::ceil(layout.size.width())),
                     static_cast<int>(std::ceil(layout.size.height())));
    generator.setSize(size);
    generator.setViewBox(QRect(QPoint(0, 0), size));
    // Text sizes are in pixels; at 96 dpi a pixel is one SVG user unit.
    generator.setResolution(96);
    generator.setTitle(title);
    generator.setDescription(QStringLiteral("Ladder network drawn by Rungsmith"));
    QPainter painter(&generator);
    paintNetwork(painter, layout, style, power);
    painter.end();
    return buffer.data();
}

QString writeNetworkPicture(const QString& path, const ladder::NetworkLayout& layout,
                            const LadderStyle& style, const PowerSnapshot* power,
                            const QString& title) {
    if (!isPictureFileName(path))
        return QStringLiteral("cannot write %1: the name must end in .svg or .png").arg(path);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
    bool written = false;
    if (hasSuffix(path, ".svg"))
        written = file.write(networkSvg(layout, style, power, title)) >= 0;
    else
        written = networkImage(layout, style, power, kPngScale).save(&file, "PNG");
    if (!written) {
        const QString error = QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
        file.cancelWriting();
        return error;
    }
    const QString reason = project::commitSaveFile(file);
    return reason.isEmpty() ? QString() : QStringLiteral("cannot write %1: %2").arg(path, reason);
}

} // namespace rs::render
