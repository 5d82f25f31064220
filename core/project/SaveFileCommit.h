// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

class QSaveFile;

namespace rs::project {

// Finishes a QSaveFile so that the destination is either the whole new content
// or untouched. QSaveFile keeps up to 16 KiB in its buffer, and Qt 6.4 commits
// the file even when flushing that buffer fails (a full disk), which replaces
// the old file by an empty one; flushing first and cancelling on failure keeps
// the old file. Returns why it failed, empty on success.
QString commitSaveFile(QSaveFile& file);

} // namespace rs::project
