// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QPointF>

class QByteArray;
class QPoint;

namespace rs::ui {

class LadderPage;

// The network whose edits a ladder page gathers until Update (F3) or Undo (F2).
struct EditSession {
    int step = 0;
    int network = 0;
};

// What a ladder page does with the mouse and with the keys whose meaning
// depends on what the user is doing: one state of the page's tools (idle,
// editing a network, dragging an element, simulating). The page creates each
// state once, hands the view's events to the current one, and a state
// switches to another through the page.
class LadderTool {
public:
    explicit LadderTool(LadderPage& page) : m_page(page) {}
    virtual ~LadderTool() = default;
    LadderTool(const LadderTool&) = delete;
    LadderTool& operator=(const LadderTool&) = delete;

    // The mouse in the view, in scene coordinates.
    virtual void pressed(const QPointF& at, Qt::MouseButton button,
                         Qt::KeyboardModifiers modifiers) = 0;
    virtual void doubleClicked(const QPointF& at) = 0;
    virtual void menuRequested(const QPointF& at, const QPoint& globalPosition) = 0;
    virtual void dragStarted(const QPointF& from) = 0;
    // Only an element dragged from this page drops on it (the payload names
    // the page), and only where the page edits.
    virtual void dropped(const QPointF& at, const QByteArray& payload, bool move);

    // Keys: Space, Enter, and the menu key.
    virtual void toggle() = 0;
    virtual void openProperties() {}
    virtual void openOperandMenu() {}

    // Whether the page edits in this state (its editing actions are enabled),
    // and whether clicks force operands.
    virtual bool edits() const { return true; }
    virtual bool forcesOperands() const { return false; }

    // The network whose edits are gathered, or nullptr; and how the state
    // ends that gathering (Update, Undo, or the project changed under it).
    virtual const EditSession* editSession() const { return nullptr; }
    virtual void endEditSession() {}

protected:
    LadderPage& m_page;
};

} // namespace rs::ui
