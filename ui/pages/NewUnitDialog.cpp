// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/NewUnitDialog.h"

#include "pages/UnitSettingsForm.h"
#include "project/Project.h"
#include "project/UnitSettings.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace rs::ui {

NewUnitDialog::NewUnitDialog(const project::Project& project, QWidget* parent)
    : QDialog(parent), m_form(new UnitSettingsForm(this)),
      m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this)) {
    setObjectName(QStringLiteral("newUnitDialog"));
    setWindowTitle(tr("New Pluto"));
    auto* intro = new QLabel(tr("Choose the Pluto type and a station number that no other unit "
                                "of the project has. The station number is part of every address "
                                "of the unit: inputs of Pluto 1 are I1.0, I1.1, ..."),
                             this);
    intro->setWordWrap(true);

    const std::vector<int> free = project::freeStations(project);
    project::UnitSettings initial;
    initial.station = free.empty() ? 0 : free.front();
    initial.type = target::UnitType::B46;
    initial.instructionSet = 3;
    m_form->setSettings(initial, free, false);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addWidget(m_form);
    layout->addStretch();
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_form, &UnitSettingsForm::edited, this, &NewUnitDialog::updateButtons);
    connect(m_form->findChild<QLineEdit*>(QStringLiteral("idfixEdit")), &QLineEdit::textEdited,
            this, &NewUnitDialog::updateButtons);
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(!free.empty());
    updateButtons();
    resize(sizeHint().expandedTo(QSize(520, 0)));
}

project::UnitSettings NewUnitDialog::settings() const {
    return m_form->settings();
}

void NewUnitDialog::updateButtons() {
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(m_form->problem().isEmpty());
}

} // namespace rs::ui
