// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/SymbolicNameDelegate.h"

#include "document/ProjectDocument.h"
#include "pages/VariableTableModel.h"
#include "shell/StatusColors.h"

#include <QAbstractProxyModel>
#include <QKeyEvent>
#include <QLineEdit>

namespace rs::ui {

namespace {

// Why the editor's name is refused, kept on the editor as it is typed.
constexpr const char* kRefusalProperty = "refusal";

const VariableTableModel* sourceModel(const QAbstractItemModel* model) {
    while (auto* proxy = qobject_cast<const QAbstractProxyModel*>(model))
        model = proxy->sourceModel();
    return qobject_cast<const VariableTableModel*>(model);
}

} // namespace

SymbolicNameDelegate::SymbolicNameDelegate(QObject* parent) : QStyledItemDelegate(parent) {}

QWidget* SymbolicNameDelegate::createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                                            const QModelIndex& index) const {
    auto* editor =
        qobject_cast<QLineEdit*>(QStyledItemDelegate::createEditor(parent, option, index));
    const VariableTableModel* model = sourceModel(index.model());
    if (!editor || !model || !model->document())
        return editor;
    editor->setObjectName(QStringLiteral("symbolicNameEditor"));
    const QString address = index.data(VariableTableModel::kAddressRole).toString();
    const lang::AddressWord word = lang::readAddressWord(address.toStdString());
    const QPalette normal = editor->palette();
    QPointer<ProjectDocument> document = model->document();
    connect(editor, &QLineEdit::textEdited, editor,
            [this, editor, document, word, normal](const QString& text) {
                if (!document)
                    return;
                const auto problem = project::checkVariableName(document->project(), word.address,
                                                                text.trimmed().toStdString());
                QPalette palette = normal;
                if (problem)
                    palette.setColor(QPalette::Text, errorTextColor(normal));
                editor->setPalette(palette);
                const QString refusal = problem ? QString::fromStdString(*problem) : QString();
                editor->setToolTip(refusal);
                editor->setProperty(kRefusalProperty, refusal);
                emit problemChanged(refusal);
            });
    return editor;
}

bool SymbolicNameDelegate::eventFilter(QObject* object, QEvent* event) {
    if (event->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent*>(event)->key();
        const bool leaving = key == Qt::Key_Return || key == Qt::Key_Enter || key == Qt::Key_Tab ||
                             key == Qt::Key_Backtab;
        const QString refusal = object->property(kRefusalProperty).toString();
        if (leaving && !refusal.isEmpty()) {
            emit problemChanged(refusal);
            return true;
        }
    }
    return QStyledItemDelegate::eventFilter(object, event);
}

} // namespace rs::ui
