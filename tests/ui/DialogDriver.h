// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <deque>
#include <functional>

class QDialog;

// Answers the modal dialogs that open next, one handler each in order, as a
// user would: the handler fills in the dialog's fields and accepts or rejects
// it. Modal dialogs run their own event loop, so the answer comes from a timer.
class DialogDriver : public QObject {
    Q_OBJECT
public:
    using Handler = std::function<void(QDialog& dialog)>;

    explicit DialogDriver(std::deque<Handler> handlers);

    // How many dialogs were handled.
    int handled() const { return m_handled; }
    bool done() const { return m_handlers.empty(); }

private:
    void poll();

    std::deque<Handler> m_handlers;
    QTimer m_timer;
    QPointer<QDialog> m_last;
    QPointer<QDialog> m_waitingFor; // shown, not yet active
    QElapsedTimer m_waiting;
    int m_handled = 0;
};
