// SPDX-License-Identifier: GPL-3.0-or-later
#include "SaveFileCommit.h"

#include <QSaveFile>

namespace rs::project {

QString commitSaveFile(QSaveFile& file) {
    if (file.error() != QFileDevice::NoError || !file.flush()) {
        const QString reason = file.errorString();
        file.cancelWriting();
        return reason;
    }
    if (!file.commit())
        return file.errorString();
    return {};
}

} // namespace rs::project
