// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStyledItemDelegate>

namespace rs::ui {

class VariableTableModel;

// Edits a symbolic name and checks it as it is typed: the editor turns red
// and says why while the name breaks the manual's rules or is taken. Return
// or Tab on a refused name keeps the editor open with what was typed, so it
// can be mended; Escape gives it up.
class SymbolicNameDelegate : public QStyledItemDelegate {
    Q_OBJECT
public:
    explicit SymbolicNameDelegate(QObject* parent = nullptr);

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option,
                          const QModelIndex& index) const override;

protected:
    bool eventFilter(QObject* object, QEvent* event) override;

signals:
    // Why the typed name is refused; empty once it is fine.
    void problemChanged(const QString& problem) const;
};

} // namespace rs::ui
