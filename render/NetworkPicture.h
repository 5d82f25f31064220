// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "LadderStyle.h"
#include "PictureFileName.h"
#include "PowerSnapshot.h"
#include "ladder/Layout.h"

#include <QByteArray>
#include <QImage>
#include <QString>

namespace rs::render {

// A network as a raster image, `scale` device pixels per layout unit.
QImage networkImage(const ladder::NetworkLayout& layout, const LadderStyle& style,
                    const PowerSnapshot* power = nullptr, qreal scale = 1);

// A network as an SVG document, one user unit per layout unit.
QByteArray networkSvg(const ladder::NetworkLayout& layout, const LadderStyle& style,
                      const PowerSnapshot* power = nullptr, const QString& title = {});

// Writes the network to a file whose name ends in .svg or .png (as SVG, or
// as PNG at twice the layout's size, sharp on high-density screens). Returns
// an error message naming the file, empty on success.
QString writeNetworkPicture(const QString& path, const ladder::NetworkLayout& layout,
                            const LadderStyle& style, const PowerSnapshot* power = nullptr,
                            const QString& title = {});

} // namespace rs::render
