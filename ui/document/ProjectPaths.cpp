// SPDX-License-Identifier: GPL-3.0-or-later
#include "document/ProjectPaths.h"

#include "document/ProjectDocument.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

namespace rs::ui {

namespace {

const QString kDirectoryKey = QStringLiteral("mainWindow/lastDirectory");

} // namespace

bool hasOwnFile(const ProjectDocument& document) {
    return !document.path().isEmpty() && !document.path().startsWith(QLatin1Char(':'));
}

QString suggestedPath(const ProjectDocument& document) {
    return hasOwnFile(document) ? document.path()
                                : QDir(lastDirectory()).filePath(document.displayName());
}

QString lastDirectory() {
    const QString stored = QSettings().value(kDirectoryKey).toString();
    return stored.isEmpty() ? QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)
                            : stored;
}

void rememberDirectory(const QString& path) {
    QSettings().setValue(kDirectoryKey, QFileInfo(path).absolutePath());
}

} // namespace rs::ui
