// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

class QLabel;

namespace rs::ui {

// A dialog's line that says why OK is refused: in the error colour, and the
// dialog grows to show it whole, so that it never covers the fields or the
// buttons below it (issue 17).
void sayProblem(QLabel* label, const QString& text);

} // namespace rs::ui
