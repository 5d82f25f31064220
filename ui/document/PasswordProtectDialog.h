// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "project/ProtectionKeys.h"
#endif

#include <QDialog>

#include <optional>

class QCheckBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QRadioButton;

namespace rs::ui {

// File > Password Protect (manual Part 1, 4.1): "Password protect source
// file", the main password, and who may change the Config Options. Unchecked
// on a protected project, it takes the protection off.
class PasswordProtectDialog : public QDialog {
    Q_OBJECT
public:
    PasswordProtectDialog(const std::optional<project::Protection>& current,
                          QWidget* parent = nullptr);

    // What OK chose: a new protection with its keys, or none (protection off).
    const std::optional<project::NewProtection>& protection() const { return m_protection; }
    void accept() override;

private:
    void updateFields();

    QCheckBox* m_protect;
    QLineEdit* m_password;
    QLineEdit* m_repeat;
    QGroupBox* m_optionsBox;
    QRadioButton* m_main;
    QRadioButton* m_free;
    QRadioButton* m_own;
    QLineEdit* m_optionsPassword;
    QLineEdit* m_optionsRepeat;
    QLabel* m_problem;
    std::optional<project::NewProtection> m_protection;
};

} // namespace rs::ui
