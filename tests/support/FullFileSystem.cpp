// SPDX-License-Identifier: GPL-3.0-or-later
#include "FullFileSystem.h"

#include <QFile>

#include <sys/mount.h>
#include <sys/statvfs.h>

#include <cerrno>
#include <cstring>

namespace rs::test {

FullFileSystem::FullFileSystem(int kilobytes) {
    if (!m_folder.isValid()) {
        m_reason = QStringLiteral("no temporary folder");
        return;
    }
    const QByteArray target = QFile::encodeName(m_folder.path());
    const QByteArray options = "size=" + QByteArray::number(kilobytes) + "k,mode=0777";
    if (::mount("rungsmith-test", target.constData(), "tmpfs", MS_NOSUID | MS_NODEV,
                options.constData()) != 0) {
        m_reason = QStringLiteral("cannot mount a tmpfs (needs root): %1")
                       .arg(QString::fromLocal8Bit(std::strerror(errno)));
        return;
    }
    m_mounted = true;
}

FullFileSystem::~FullFileSystem() {
    if (m_mounted)
        ::umount2(QFile::encodeName(m_folder.path()).constData(), MNT_DETACH);
}

QString FullFileSystem::filePath(const QString& name) const {
    return m_folder.filePath(name);
}

bool FullFileSystem::put(const QString& name, const QByteArray& bytes) const {
    QFile file(filePath(name));
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size() && file.flush();
}

bool FullFileSystem::fill() const {
    QFile filler(filePath(QStringLiteral(".filler")));
    if (!filler.open(QIODevice::WriteOnly | QIODevice::Unbuffered))
        return false;
    const QByteArray block(4096, 'x');
    while (filler.write(block) > 0) {
    }
    filler.close();
    struct statvfs stats {};
    return ::statvfs(QFile::encodeName(m_folder.path()).constData(), &stats) == 0 &&
           stats.f_bavail == 0;
}

} // namespace rs::test
