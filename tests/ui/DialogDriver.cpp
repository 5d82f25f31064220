// SPDX-License-Identifier: GPL-3.0-or-later
#include "DialogDriver.h"

#include <QApplication>
#include <QDialog>

#include <gtest/gtest.h>

DialogDriver::DialogDriver(std::deque<Handler> handlers) : m_handlers(std::move(handlers)) {
    connect(&m_timer, &QTimer::timeout, this, &DialogDriver::poll);
    m_timer.start(10);
}

void DialogDriver::poll() {
    auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
    if (!dialog || !dialog->isVisible() || dialog == m_last || m_handlers.empty())
        return;
    // Keys go to a dialog's shortcuts only once it is the active window; on a
    // busy machine that can come a while after it shows.
    constexpr int kActivationWaitMs = 2000;
    if (!dialog->isActiveWindow()) {
        if (dialog != m_waitingFor) {
            m_waitingFor = dialog;
            m_waiting.start();
        }
        if (m_waiting.elapsed() < kActivationWaitMs)
            return;
    }
    m_last = dialog;
    Handler handler = std::move(m_handlers.front());
    m_handlers.pop_front();
    ++m_handled;
    handler(*dialog);
    // A handler stopped by a failed ASSERT leaves its dialog open, and the
    // modal loop would wait for it forever: closing it lets the test end
    // with its failure.
    if (::testing::Test::HasFatalFailure() && dialog->isVisible())
        dialog->reject();
    if (m_handlers.empty())
        m_timer.stop();
}
