// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

class QSaveFile;

namespace rs::project {

// Writes the pieces of a file on a thread of its own while the caller makes
// the next ones, and has the kernel start putting each megabyte on the disk
// as soon as it is written. A large image (21.6 MB of Intel HEX) was made,
// written and then waited for at commit, one after the other; now the
// writing and most of the disk's work happen while it is made (issue 23).
class WriteBehind {
public:
    explicit WriteBehind(QSaveFile& file);
    // Without finish(): the pieces still queued are dropped (the caller
    // cancels the file).
    ~WriteBehind();
    WriteBehind(const WriteBehind&) = delete;
    WriteBehind& operator=(const WriteBehind&) = delete;

    // Queues a copy of the piece; waits while kQueued pieces are waiting.
    void add(std::string_view piece);
    // Waits until every piece is written. The reason of the first failure,
    // after which nothing more was tried; empty when all were written.
    QString finish();

    static constexpr std::size_t kQueued = 4;
    // Write-back is started in steps of this many bytes.
    static constexpr std::size_t kWriteBackStep = std::size_t{1} << 20;

private:
    void run();
    void write(const std::string& piece);

    QSaveFile& m_file;
    std::mutex m_mutex;
    std::condition_variable m_changed;
    std::deque<std::string> m_queued;
    std::vector<std::string> m_spare; // written pieces' buffers, their capacity kept
    bool m_closing = false;
    QString m_error;               // the writer's; read by the caller after the join
    std::size_t m_written = 0;     // the writer's
    std::size_t m_writtenBack = 0; // the writer's: bytes whose write-back has started
    std::thread m_thread;          // last: started when the rest is ready
};

} // namespace rs::project
