// SPDX-License-Identifier: GPL-3.0-or-later
#include "MessageBoxAnswerer.h"

#include <QAbstractButton>
#include <QApplication>
#include <QPushButton>

MessageBoxAnswerer::MessageBoxAnswerer(QMessageBox::StandardButton answer) : m_answer(answer) {
    connect(&m_timer, &QTimer::timeout, this, &MessageBoxAnswerer::poll);
    m_timer.start(10);
}

void MessageBoxAnswerer::poll() {
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    if (!box || !box->isVisible())
        return;
    m_timer.stop();
    m_answered = true;
    m_text = box->text();
    m_informativeText = box->informativeText();
    m_buttons = box->standardButtons();
    // A box without that button gets the answer of the Enter key: its default button.
    if (QAbstractButton* button = box->button(m_answer))
        button->click();
    else if (QPushButton* fallback = box->defaultButton())
        fallback->click();
    else
        box->reject();
}
