// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "LadderTool.h"

namespace rs::ui {

// Simulating: the page is for watching and forcing. A click (or Space) on an
// element with an operand reports the operand, a right click (or the menu
// key) asks for its forcing menu; networks still expand and collapse, and
// nothing edits.
class LiveTool : public LadderTool {
public:
    using LadderTool::LadderTool;

    void pressed(const QPointF& at, Qt::MouseButton button,
                 Qt::KeyboardModifiers modifiers) override;
    void doubleClicked(const QPointF&) override {}
    void menuRequested(const QPointF& at, const QPoint& globalPosition) override;
    void dragStarted(const QPointF&) override {}
    void toggle() override;
    void openOperandMenu() override;
    bool edits() const override { return false; }
    bool forcesOperands() const override { return true; }
};

} // namespace rs::ui
