// SPDX-License-Identifier: GPL-3.0-or-later
#include "shell/CompleterKeys.h"

#include <QAbstractItemView>
#include <QCompleter>
#include <QCoreApplication>
#include <QKeyEvent>
#include <QLineEdit>

namespace rs::ui {

namespace {

// Watches the list before the completer does (filters installed later run first).
class CompletionKeyFilter : public QObject {
public:
    explicit CompletionKeyFilter(QCompleter* completer)
        : QObject(completer), m_completer(completer) {}

    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() != QEvent::KeyPress)
            return QObject::eventFilter(watched, event);
        auto* key = static_cast<QKeyEvent*>(event);
        const bool confirm = key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter;
        if (!confirm && key->key() != Qt::Key_Escape)
            return QObject::eventFilter(watched, event);
        auto* edit = qobject_cast<QLineEdit*>(m_completer->widget());
        if (!edit)
            return QObject::eventFilter(watched, event);
        const QModelIndex chosen = m_completer->popup()->currentIndex();
        if (confirm && chosen.isValid())
            edit->setText(chosen.data(m_completer->completionRole()).toString());
        m_completer->popup()->hide();
        // The line edit takes it first (returnPressed), then its window if it ignores it.
        QKeyEvent again(QEvent::KeyPress, key->key(), key->modifiers(), key->text());
        QCoreApplication::sendEvent(edit, &again);
        return true;
    }

private:
    QCompleter* m_completer;
};

} // namespace

void finishCompletionInOneKey(QCompleter* completer) {
    completer->popup()->installEventFilter(new CompletionKeyFilter(completer));
}

} // namespace rs::ui
