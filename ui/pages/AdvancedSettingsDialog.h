// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

class QCheckBox;
class QSpinBox;

namespace rs::ui {

// A unit's Advanced settings (manual Part 1, 5.2): the CAN bus cycle time,
// the unit's default or a time in milliseconds, under the manual's warning.
class AdvancedSettingsDialog : public QDialog {
    Q_OBJECT
public:
    // `canCycleMs` 0 is the default.
    AdvancedSettingsDialog(int station, int canCycleMs, QWidget* parent = nullptr);

    int canCycleMs() const; // 0: the default

private:
    QCheckBox* m_set;
    QSpinBox* m_cycle;
};

} // namespace rs::ui
