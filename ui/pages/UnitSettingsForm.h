// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

#include <vector>

class QButtonGroup;
class QComboBox;
class QLabel;
class QLineEdit;
class QRadioButton;

namespace rs::project {
struct UnitSettings;
}

namespace rs::ui {

// The fields of a unit (manual Part 1, 3.6 and 5): station, Pluto type,
// instruction set 2 or 3 with the manual's explanation, IDFIX number or
// "No IDFIX", and description. Only what the unit can be is offered: free
// stations, instruction set 3 only for the types that run it, IDFIX as 12
// hexadecimal digits.
class UnitSettingsForm : public QWidget {
    Q_OBJECT
public:
    explicit UnitSettingsForm(QWidget* parent = nullptr);

    // The stations offered; the unit's own one is always among them. With a
    // fixed station (an existing unit) the station is shown, not chosen.
    void setSettings(const project::UnitSettings& settings, const std::vector<int>& freeStations,
                     bool stationFixed);
    project::UnitSettings settings() const;

    // Why the fields do not make a unit yet (an IDFIX with too few digits), empty when they do.
    QString problem() const;

signals:
    // The user changed a field: choices at once, typed text when editing ends.
    void edited();

private:
    void updateInstructionSets();
    void updateIdfix();

    QComboBox* m_station;
    QComboBox* m_type;
    QRadioButton* m_set2;
    QRadioButton* m_set3;
    QButtonGroup* m_sets;
    QLabel* m_setNote;
    QComboBox* m_idfixKind;
    QLineEdit* m_idfix;
    QLineEdit* m_description;
    QLabel* m_problem;
    bool m_filling = false;
};

} // namespace rs::ui
