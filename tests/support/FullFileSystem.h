// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QTemporaryDir>

namespace rs::test {

// A small tmpfs mounted on a temporary folder and filled to the last byte, so
// that a test writes to a really full disk. Mounting needs root (CI and the
// developers' machines run the suite as root); available() says whether the
// mount succeeded and reason() why not.
class FullFileSystem {
public:
    // Room for a few small files by default; the filler takes the rest.
    explicit FullFileSystem(int kilobytes = 256);
    ~FullFileSystem();
    FullFileSystem(const FullFileSystem&) = delete;
    FullFileSystem& operator=(const FullFileSystem&) = delete;

    bool available() const { return m_mounted; }
    QString reason() const { return m_reason; }

    // A path inside the file system.
    QString filePath(const QString& name) const;

    // Writes a file while there is room (call before fill()).
    bool put(const QString& name, const QByteArray& bytes) const;

    // Takes every free byte; returns false if the file system still has room.
    bool fill() const;

private:
    QTemporaryDir m_folder;
    bool m_mounted = false;
    QString m_reason;
};

} // namespace rs::test
