// SPDX-License-Identifier: GPL-3.0-or-later
#include "document/Autosave.h"

#include "document/ProjectDocument.h"
#include "project/ProjectFile.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLockFile>
#include <QStandardPaths>

#include <map>
#include <memory>

namespace rs::ui {

namespace {

QString& overriddenDirectory() {
    static QString directory;
    return directory;
}

QString textPath(const QString& id) {
    return QDir(Autosave::directory()).filePath(id + QStringLiteral(".sps"));
}

QString infoPath(const QString& id) {
    return QDir(Autosave::directory()).filePath(id + QStringLiteral(".json"));
}

QString lockPath(const QString& id) {
    return QDir(Autosave::directory()).filePath(id + QStringLiteral(".lock"));
}

// The locks this process holds, by copy.
std::map<QString, std::unique_ptr<QLockFile>>& locks() {
    static std::map<QString, std::unique_ptr<QLockFile>> held;
    return held;
}

// A lock that only a running process holds: never stale by age.
std::unique_ptr<QLockFile> lockFor(const QString& id) {
    auto lock = std::make_unique<QLockFile>(lockPath(id));
    lock->setStaleLockTime(0);
    return lock;
}

} // namespace

QString Autosave::directory() {
    if (!overriddenDirectory().isEmpty())
        return overriddenDirectory();
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
        .filePath(QStringLiteral("autosave"));
}

void Autosave::setDirectory(const QString& directory) {
    overriddenDirectory() = directory;
}

QString Autosave::write(const ProjectDocument& document) {
    return write(document.autosaveId(), document.path(), document.displayName(),
                 document.fileText());
}

QString Autosave::write(const QString& id, const QString& path, const QString& displayName,
                        const QByteArray& text) {
    if (!QDir().mkpath(directory()))
        return QStringLiteral("cannot create %1").arg(directory());
    if (!locks().count(id)) {
        auto lock = lockFor(id);
        if (lock->tryLock(0))
            locks()[id] = std::move(lock);
    }
    // The index first: a crash between the two writes leaves the index with
    // the previous copy (or none yet), never a copy that recovery cannot name.
    const QJsonObject info{
        {QStringLiteral("path"), path},
        {QStringLiteral("name"), displayName},
        {QStringLiteral("written"), QDateTime::currentDateTime().toString(Qt::ISODate)}};
    const QByteArray json = QJsonDocument(info).toJson();
    if (QString error = project::writeTextFile(
            infoPath(id),
            std::string_view(json.constData(), static_cast<std::size_t>(json.size())));
        !error.isEmpty())
        return error;
    return project::writeTextFile(
        textPath(id), std::string_view(text.constData(), static_cast<std::size_t>(text.size())));
}

void Autosave::remove(const QString& id) {
    QFile::remove(textPath(id));
    QFile::remove(infoPath(id));
    release(id);
}

void Autosave::release(const QString& id) {
    locks().erase(id);
}

QList<Autosave::Copy> Autosave::copies() {
    QList<Copy> found;
    const QDir folder(directory());
    // By copy, not by index: a copy whose index is missing or unreadable is
    // still someone's work.
    for (const QString& name :
         folder.entryList({QStringLiteral("*.sps")}, QDir::Files, QDir::Time)) {
        Copy copy;
        copy.id = name.chopped(4);
        copy.copyPath = folder.filePath(name);
        // A lock that cannot be taken belongs to a Rungsmith still running.
        auto probe = lockFor(copy.id);
        if (locks().count(copy.id) || !probe->tryLock(0))
            continue;
        probe->unlock();
        QFile file(infoPath(copy.id));
        const QJsonObject info = file.open(QIODevice::ReadOnly)
                                     ? QJsonDocument::fromJson(file.readAll()).object()
                                     : QJsonObject();
        copy.path = info.value(QStringLiteral("path")).toString();
        copy.displayName = info.value(QStringLiteral("name")).toString();
        copy.written =
            QDateTime::fromString(info.value(QStringLiteral("written")).toString(), Qt::ISODate);
        if (copy.displayName.isEmpty())
            copy.displayName = copy.path.isEmpty() ? name : QFileInfo(copy.path).fileName();
        if (!copy.written.isValid())
            copy.written = QFileInfo(copy.copyPath).lastModified();
        found.append(copy);
    }
    return found;
}

} // namespace rs::ui
