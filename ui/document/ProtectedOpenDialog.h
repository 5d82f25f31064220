// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#ifndef Q_MOC_RUN
#include "project/ProtectionKeys.h"
#endif

#include <QDialog>
#include <QTimer>

class QLabel;
class QLineEdit;
class QPushButton;
class QRadioButton;

namespace rs::ui {

// The manual's question on opening a password-protected file (Part 1,
// 4.1.1): full permission, permission to configure, or read only, with the
// password each takes. A wrong password is refused without saying which
// password exists, and each refusal makes the next try wait longer.
class ProtectedOpenDialog : public QDialog {
    Q_OBJECT
public:
    ProtectedOpenDialog(const QString& fileName, const project::Protection& protection,
                        QWidget* parent = nullptr);
    // Offers full permission alone: accepting a change made outside Rungsmith.
    void askForFullPermissionOnly();

    project::Permission permission() const { return m_permission; }
    const project::Keyring& keys() const { return m_keys; }
    void accept() override;

private:
    project::Permission chosen() const;
    void updateFields();
    void tick();

    project::Protection m_protection;
    QRadioButton* m_full;
    QRadioButton* m_configure;
    QRadioButton* m_readOnly;
    QLineEdit* m_password;
    QLabel* m_problem;
    QPushButton* m_ok;
    QTimer m_wait;
    int m_refusals = 0;
    int m_secondsLeft = 0;
    project::Permission m_permission = project::Permission::ReadOnly;
    project::Keyring m_keys;
};

} // namespace rs::ui
