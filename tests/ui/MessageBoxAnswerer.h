// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QMessageBox>
#include <QObject>
#include <QTimer>

// Answers the next message box that opens, as a user would, and remembers
// what it said. A box that has no button for the answer gets its default one. Message boxes run
// their own event loop, so the answer has to come from a timer.
class MessageBoxAnswerer : public QObject {
    Q_OBJECT
public:
    explicit MessageBoxAnswerer(QMessageBox::StandardButton answer);

    bool answered() const { return m_answered; }
    QString text() const { return m_text; }
    QString informativeText() const { return m_informativeText; }
    QMessageBox::StandardButtons buttons() const { return m_buttons; }

private:
    void poll();

    QMessageBox::StandardButton m_answer;
    QTimer m_timer;
    bool m_answered = false;
    QString m_text;
    QString m_informativeText;
    QMessageBox::StandardButtons m_buttons;
};
