// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/SymbolicNameDelegate.h"

#include "document/ProjectDocument.h"
#include "pages/VariableTableModel.h"
#include "shell/StatusColors.h"

#include <QAbstractProxyModel>
#include <QLineEdit>

namespace rs::ui {

namespace {

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
                editor->setToolTip(problem ? QString::fromStdString(*problem) : QString());
                emit problemChanged(problem ? QString::fromStdString(*problem) : QString());
            });
    return editor;
}

} // namespace rs::ui
