// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "IdleTool.h"

namespace rs::ui {

// A network in edit mode (manual 11.1, 11.3): the mouse and keys work as
// when idle, but the edits of the network gather in the page's copy of it
// until Update (F3) makes them one undo step or Undo (F2) drops them.
class NetworkEditTool : public IdleTool {
public:
    using IdleTool::IdleTool;

    void start(const EditSession& session) { m_session = session; }
    const EditSession* editSession() const override { return &m_session; }
    // The session is over: the page rests again.
    void endEditSession() override;

private:
    EditSession m_session;
};

} // namespace rs::ui
