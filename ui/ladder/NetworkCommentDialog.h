// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

class QPlainTextEdit;

namespace rs::ui {

// A network's comment: several lines, wrapped at the window's width as it is
// typed. It is used from the keyboard alone: Tab moves on to the buttons (a
// comment has no tabs), Return starts a new line and Ctrl+Return confirms.
class NetworkCommentDialog : public QDialog {
    Q_OBJECT
public:
    NetworkCommentDialog(const QString& label, const QString& text, QWidget* parent = nullptr);

    QString text() const;
    QPlainTextEdit* editor() const { return m_editor; }

private:
    QPlainTextEdit* m_editor;
};

} // namespace rs::ui
