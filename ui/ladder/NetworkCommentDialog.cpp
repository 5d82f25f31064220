// SPDX-License-Identifier: GPL-3.0-or-later
#include "NetworkCommentDialog.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace rs::ui {

NetworkCommentDialog::NetworkCommentDialog(const QString& label, const QString& text,
                                           QWidget* parent)
    : QDialog(parent), m_editor(new QPlainTextEdit(text, this)) {
    setWindowTitle(tr("Network Comment"));
    m_editor->setObjectName(QStringLiteral("commentEditor"));
    m_editor->setTabChangesFocus(true);
    m_editor->setLineWrapMode(QPlainTextEdit::WidgetWidth);
    m_editor->setWordWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    m_editor->moveCursor(QTextCursor::End);
    auto* caption = new QLabel(label, this);
    caption->setBuddy(m_editor);
    auto* hint = new QLabel(tr("Return starts a new line; Ctrl+Return confirms."), this);
    hint->setEnabled(false);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(caption);
    layout->addWidget(m_editor, 1);
    layout->addWidget(hint);
    layout->addWidget(buttons);
    resize(480, 260);

    auto* confirm = new QAction(this);
    confirm->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::Key_Return), QKeySequence(Qt::CTRL | Qt::Key_Enter)});
    confirm->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    addAction(confirm);
    connect(confirm, &QAction::triggered, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

QString NetworkCommentDialog::text() const {
    return m_editor->toPlainText();
}

} // namespace rs::ui
