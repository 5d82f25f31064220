// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProgramFile.h"

#include "ProgramText.h"

#include <QFile>

namespace rs::pl110 {

bool isPl110File(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return false;
    const QByteArray start = file.read(64 * 1024);
    return isPl110Text({start.constData(), static_cast<std::size_t>(start.size())});
}

} // namespace rs::pl110
