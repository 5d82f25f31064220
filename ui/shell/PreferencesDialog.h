// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "shell/Preferences.h"

#include <QDialog>

#include <vector>

class QCheckBox;
class QComboBox;
class QLineEdit;
class QSpinBox;
class QToolButton;

namespace rs::ui {

// Edit > Preferences (manual Part 1, 14): ladder colours with a way back to
// the defaults, the screen update interval, start with ladder diagrams
// expanded, unconfigured-I/O warnings at compile time, the language, and the
// theme and autosave interval of this IDE.
class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    explicit PreferencesDialog(const Preferences& preferences, QWidget* parent = nullptr);

    Preferences preferences() const;

private:
    struct ColorField {
        QColor Preferences::*member;
        QToolButton* button;
    };
    void setColor(ColorField& field, const QColor& color);
    void show(const Preferences& preferences);

    Preferences m_preferences;
    std::vector<ColorField> m_colors;
    QComboBox* m_updateInterval;
    QCheckBox* m_startExpanded;
    QCheckBox* m_warnUnconfiguredIo;
    QComboBox* m_language;
    QComboBox* m_theme;
    QSpinBox* m_autosave;
    QLineEdit* m_modbusHost;
    QSpinBox* m_modbusPort;
};

} // namespace rs::ui
