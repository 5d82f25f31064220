#include "SaveFileCommit.h"

#include <QSaveFile>

namespace rs::project {

QString commitSaveFile(QSaveFile& file) {
    const auto failure = [&file] {
        const QString message =
            QStringLiteral("cannot write %1: %2").arg(file.fileName(), file.errorString());
        file.cancelWriting();
        return message;
    };
    if (file.error() != QFileDevice::NoError || !file.flush())
        return failure();
    if (!file.commit())
        return QStringLiteral("cannot write %1: %2").arg(file.fileName(), file.errorString());
    return {};
}

} // namespace rs::project
