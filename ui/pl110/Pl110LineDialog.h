// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

#include <functional>

class QDialogButtonBox;
class QLabel;
class QLineEdit;

namespace rs::ui {

// Asks for one line of PL110 text (a rung, or a contact or condition) and
// reads it as it is typed: the reader's message, with its column, shows
// below the line, and OK takes only text that reads.
class Pl110LineDialog : public QDialog {
    Q_OBJECT
public:
    // `problem` returns why the text does not read, empty when it does.
    Pl110LineDialog(const QString& title, const QString& label, const QString& text,
                    std::function<QString(const QString&)> problem, QWidget* parent = nullptr);

    QString text() const;

private:
    void check();

    std::function<QString(const QString&)> m_problem;
    QLineEdit* m_line;
    QLabel* m_message;
    QDialogButtonBox* m_buttons;
};

} // namespace rs::ui
