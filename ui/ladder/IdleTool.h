// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "LadderTool.h"

namespace rs::ui {

// The page's resting state: a click selects (Ctrl and Shift choose several
// networks), a double click opens what it hit, dragging an element moves it,
// Space toggles a Config Option, Enter opens the properties, and every edit
// is one undo step of the project.
class IdleTool : public LadderTool {
public:
    using LadderTool::LadderTool;

    void pressed(const QPointF& at, Qt::MouseButton button,
                 Qt::KeyboardModifiers modifiers) override;
    void doubleClicked(const QPointF& at) override;
    void menuRequested(const QPointF& at, const QPoint& globalPosition) override;
    void dragStarted(const QPointF& from) override;
    void toggle() override;
    void openProperties() override;
};

} // namespace rs::ui
