// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "LadderTool.h"

namespace rs::ui {

// An element being dragged: a drop on an element of the page copies it (with
// Shift moves it) next to that element, before or after it by which half the
// drop hit (LadderTool::dropped). The
// drag runs to its end within run(); then the state the drag began in
// resumes (an edit session the drop ended resumes as idle).
class DragTool : public LadderTool {
public:
    using LadderTool::LadderTool;

    // Drags the element at `from`, then switches the page back to `resume`.
    void run(const QPointF& from, LadderTool& resume);

    void pressed(const QPointF&, Qt::MouseButton, Qt::KeyboardModifiers) override {}
    void doubleClicked(const QPointF&) override {}
    void menuRequested(const QPointF&, const QPoint&) override {}
    void dragStarted(const QPointF&) override {}
    void toggle() override {}
    const EditSession* editSession() const override;
    void endEditSession() override;

private:
    LadderTool* m_resume = nullptr;
};

} // namespace rs::ui
