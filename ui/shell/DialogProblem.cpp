// SPDX-License-Identifier: GPL-3.0-or-later
#include "shell/DialogProblem.h"

#include "shell/StatusColors.h"

#include <QLabel>
#include <QLayout>

namespace rs::ui {

void sayProblem(QLabel* label, const QString& text) {
    markAsError(label);
    label->setWordWrap(true);
    label->setText(text);
    label->setVisible(!text.isEmpty());
    QWidget* window = label->window();
    QLayout* layout = window->layout();
    if (!layout)
        return;
    layout->invalidate();
    layout->activate();
    // A wrapped label knows its height only for a width, so the window asks
    // for its own width; it only grows, never jumps narrower.
    const int width = window->width();
    const int height = layout->hasHeightForWidth() ? layout->totalHeightForWidth(width)
                                                   : layout->totalSizeHint().height();
    if (height > window->height())
        window->resize(width, height);
}

} // namespace rs::ui
