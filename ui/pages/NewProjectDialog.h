// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

class QCheckBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;

namespace rs::ui {

// File > New (manual Part 1, 3.1 to 3.3): the project name downloaded to
// the units, a description for the user's notes, and whether the compiled
// file carries the source code.
class NewProjectDialog : public QDialog {
    Q_OBJECT
public:
    explicit NewProjectDialog(QWidget* parent = nullptr);

    QString name() const;
    QString description() const;
    bool includeSource() const;

private:
    void validate();

    QLineEdit* m_name;
    QPlainTextEdit* m_description;
    QCheckBox* m_includeSource;
    QLabel* m_problem;
    QDialogButtonBox* m_buttons;
};

} // namespace rs::ui
