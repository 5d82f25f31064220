// SPDX-License-Identifier: GPL-3.0-or-later
#include "PictureFileName.h"

namespace rs::render {

bool isPictureFileName(const QString& path) {
    return path.endsWith(QLatin1String(".svg"), Qt::CaseInsensitive) ||
           path.endsWith(QLatin1String(".png"), Qt::CaseInsensitive);
}

} // namespace rs::render
