// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

class QDialogButtonBox;

namespace rs::project {
struct Project;
struct UnitSettings;
} // namespace rs::project

namespace rs::ui {

class UnitSettingsForm;

// "New Pluto" (manual Part 1, 3.6 and 5): type of every family, a free
// station 0-31, instruction set, IDFIX and description.
class NewUnitDialog : public QDialog {
    Q_OBJECT
public:
    explicit NewUnitDialog(const project::Project& project, QWidget* parent = nullptr);

    project::UnitSettings settings() const;
    UnitSettingsForm* form() const { return m_form; }

private:
    void updateButtons();

    UnitSettingsForm* m_form;
    QDialogButtonBox* m_buttons;
};

} // namespace rs::ui
