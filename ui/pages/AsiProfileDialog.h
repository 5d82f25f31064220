// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Holds a core type by value; Qt 6.4's moc cannot parse the C++20 headers
// it brings in and needs only the name.
#ifndef Q_MOC_RUN
#include "project/AsiOptions.h"
#endif

#include <QDialog>

class QComboBox;
class QLabel;

namespace rs::ui {

// The AS-i Profile box of the AS-i Options page (manual Part 1, 7.1.4): the
// slave's profile S-<I/O configuration>.<ID code>.<ID2> and its ID1, each a
// hexadecimal digit, with the profile as the table will show it.
class AsiProfileDialog : public QDialog {
    Q_OBJECT
public:
    AsiProfileDialog(const QString& slave, const project::AsiProfile& profile,
                     QWidget* parent = nullptr);

    project::AsiProfile profile() const;
    QComboBox* digitBox(int part) const; // 0 I/O configuration, 1 ID code, 2 ID2, 3 ID1

private:
    void showProfile();

    QString m_slave;
    QComboBox* m_digits[4];
    QLabel* m_summary;
};

} // namespace rs::ui
