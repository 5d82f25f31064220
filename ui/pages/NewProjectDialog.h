// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;

namespace rs::ui {

// File > New (manual Part 1, 3.1 to 3.3): the target (Pluto units, or a
// Pixsys PL110, docs/pl110.md), the project name downloaded to the units, a
// description for the user's notes, and whether the compiled file carries
// the source code (the last two are Pluto's).
class NewProjectDialog : public QDialog {
    Q_OBJECT
public:
    explicit NewProjectDialog(QWidget* parent = nullptr);

    enum class Target { Pluto, Pl110 };
    Target target() const;
    QString name() const;
    QString description() const;
    bool includeSource() const;

private:
    void validate();

    QComboBox* m_target;
    QLineEdit* m_name;
    QPlainTextEdit* m_description;
    QCheckBox* m_includeSource;
    QLabel* m_problem;
    QDialogButtonBox* m_buttons;
};

} // namespace rs::ui
