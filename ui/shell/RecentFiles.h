// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStringList>

namespace rs::ui {

// The project files opened or saved last, newest first, kept in the user's
// settings so that they survive a restart.
class RecentFiles {
public:
    static constexpr int kLimit = 10;

    QStringList paths() const;
    void add(const QString& path);
    void clear();
};

} // namespace rs::ui
