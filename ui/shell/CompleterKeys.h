// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

class QCompleter;

namespace rs::ui {

// With a completion list open, Return takes the chosen completion (if any)
// and confirms at once, as it does with the list closed, and Escape goes to
// the window (a dialog cancels): the list opens by itself while typing, so a
// key that only closed it would be a trap (issue 17).
void finishCompletionInOneKey(QCompleter* completer);

} // namespace rs::ui
