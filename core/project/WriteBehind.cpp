// SPDX-License-Identifier: GPL-3.0-or-later
#include "WriteBehind.h"

#include <QSaveFile>

#include <fcntl.h>

namespace rs::project {

WriteBehind::WriteBehind(QSaveFile& file) : m_file(file), m_thread([this] { run(); }) {}

WriteBehind::~WriteBehind() {
    if (!m_thread.joinable())
        return;
    {
        const std::lock_guard lock(m_mutex);
        m_queued.clear();
        m_closing = true;
    }
    m_changed.notify_all();
    m_thread.join();
}

void WriteBehind::add(std::string_view piece) {
    if (piece.empty())
        return;
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [this] { return m_queued.size() < kQueued; });
    std::string buffer;
    if (!m_spare.empty()) {
        buffer = std::move(m_spare.back());
        m_spare.pop_back();
    }
    buffer.assign(piece);
    m_queued.push_back(std::move(buffer));
    lock.unlock();
    m_changed.notify_all();
}

QString WriteBehind::finish() {
    {
        const std::lock_guard lock(m_mutex);
        m_closing = true;
    }
    m_changed.notify_all();
    m_thread.join();
    return m_error;
}

void WriteBehind::run() {
    for (;;) {
        std::string piece;
        {
            std::unique_lock lock(m_mutex);
            m_changed.wait(lock, [this] { return m_closing || !m_queued.empty(); });
            if (m_queued.empty())
                return;
            piece = std::move(m_queued.front());
            m_queued.pop_front();
        }
        m_changed.notify_all();
        write(piece);
        const std::lock_guard lock(m_mutex);
        m_spare.push_back(std::move(piece));
    }
}

void WriteBehind::write(const std::string& piece) {
    if (!m_error.isEmpty())
        return;
    if (m_file.write(piece.data(), static_cast<qint64>(piece.size())) !=
        static_cast<qint64>(piece.size())) {
        m_error = m_file.errorString();
        return;
    }
    m_written += piece.size();
#ifdef SYNC_FILE_RANGE_WRITE
    if (m_written - m_writtenBack < kWriteBackStep)
        return;
    // What Qt still holds goes to the file first; a failure there is the
    // first failure, as a write's would be.
    if (!m_file.flush()) {
        m_error = m_file.errorString();
        return;
    }
    // A hint: the commit's fdatasync still waits for whatever is not on the
    // disk, so a file system that cannot start write-back early loses nothing.
    sync_file_range(m_file.handle(), static_cast<off_t>(m_writtenBack),
                    static_cast<off_t>(m_written - m_writtenBack), SYNC_FILE_RANGE_WRITE);
    m_writtenBack = m_written;
#endif
}

} // namespace rs::project
