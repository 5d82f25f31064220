// SPDX-License-Identifier: GPL-3.0-or-later
#include "LibrarySearch.h"

#include "LibraryLimits.h"
#include "LibraryReader.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>

namespace rs::blocks {

QStringList standardLibraryFolders(const QString& executableDir) {
    const QStringList candidates{
        QDir(executableDir).filePath(QStringLiteral("libraries")),
        QDir(executableDir).filePath(QStringLiteral("../share/rungsmith/libraries")),
        QStringLiteral("/usr/share/rungsmith/libraries"),
    };
    QStringList folders;
    for (const QString& candidate : candidates) {
        const QFileInfo info(candidate);
        if (!info.isDir())
            continue;
        const QString canonical = info.canonicalFilePath();
        if (!folders.contains(canonical))
            folders.append(canonical);
    }
    return folders;
}

QStringList libraryFilesIn(const QString& folder) {
    const QDir dir(folder);
    QStringList files;
    for (const QString& name :
         dir.entryList({QStringLiteral("*.") + QLatin1String(kLibraryExtension)},
                       QDir::Files | QDir::Readable, QDir::Name))
        files.append(dir.filePath(name));
    return files;
}

bool LibrarySet::ok() const {
    for (const auto& problem : problems)
        if (!problem.readError.isEmpty() || lang::errorCount(problem.diagnostics) > 0)
            return false;
    return true;
}

const LoadedLibrary* LibrarySet::findLibrary(std::string_view name) const {
    for (const auto& loaded : libraries)
        if (sameName(loaded.library.name, name))
            return &loaded;
    return nullptr;
}

const LoadedLibrary* LibrarySet::libraryOfBlock(std::string_view blockName) const {
    for (const auto& loaded : libraries)
        if (loaded.library.findBlock(blockName))
            return &loaded;
    return nullptr;
}

void addLibraryFile(LibrarySet& set, const QString& path, LibraryOrigin origin) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        set.problems.push_back(
            {path, QStringLiteral("cannot read %1: %2").arg(path, file.errorString()), {}});
        return;
    }
    // One byte past the limit is enough for the reader to refuse the file.
    // Read in pieces: QIODevice::read(n) allocates n bytes before reading.
    const qint64 limit = static_cast<qint64>(kMaxLibraryBytes) + 1;
    QByteArray bytes;
    while (bytes.size() < limit) {
        const QByteArray piece = file.read(std::min<qint64>(qint64{1} << 16, limit - bytes.size()));
        if (piece.isEmpty())
            break;
        bytes += piece;
    }
    if (file.error() != QFileDevice::NoError) {
        set.problems.push_back(
            {path, QStringLiteral("cannot read %1: %2").arg(path, file.errorString()), {}});
        return;
    }
    LibraryReadResult read = readLibrary(std::string_view(bytes.constData(), bytes.size()));
    if (read.ok()) {
        if (const LoadedLibrary* earlier = set.findLibrary(read.library.name)) {
            read.diagnostics.push_back(
                {lang::Severity::Warning, 1, 1,
                 "library '" + read.library.name + "' is already loaded from " +
                     earlier->path.toStdString() + "; this file is not used"});
        } else {
            set.libraries.push_back({std::move(read.library), path, origin});
        }
    }
    if (!read.diagnostics.empty())
        set.problems.push_back({path, {}, std::move(read.diagnostics)});
}

LibrarySet loadLibraries(const QStringList& standardFolders, const QString& projectFolder,
                         const QStringList& userFiles) {
    LibrarySet set;
    for (const QString& folder : standardFolders)
        for (const QString& path : libraryFilesIn(folder))
            addLibraryFile(set, path, LibraryOrigin::Standard);
    if (!projectFolder.isEmpty())
        for (const QString& path : libraryFilesIn(projectFolder))
            addLibraryFile(set, path, LibraryOrigin::User);
    for (const QString& path : userFiles)
        addLibraryFile(set, path, LibraryOrigin::User);
    return set;
}

} // namespace rs::blocks
