// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/AdvancedSettingsDialog.h"

#include "project/CanBusCycle.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>

namespace rs::ui {

AdvancedSettingsDialog::AdvancedSettingsDialog(int station, int canCycleMs, QWidget* parent)
    : QDialog(parent), m_set(new QCheckBox(tr("&Set the CAN bus cycle time:"), this)),
      m_cycle(new QSpinBox(this)) {
    setWindowTitle(tr("Advanced Settings of Pluto %1").arg(station));
    setMinimumWidth(fontMetrics().averageCharWidth() * 60);
    auto* layout = new QVBoxLayout(this);
    auto* warning = new QLabel(tr("These settings have influence on the system response time. "
                                  "Do not change these values without a good knowledge of the "
                                  "function of the system. The hardware manual describes them."),
                               this);
    warning->setWordWrap(true);
    layout->addWidget(warning);
    m_set->setObjectName(QStringLiteral("canCycleSet"));
    m_cycle->setObjectName(QStringLiteral("canCycleMs"));
    m_cycle->setRange(project::kMinCanCycleMs, project::kMaxCanCycleMs);
    m_cycle->setSuffix(tr(" ms"));
    m_set->setChecked(canCycleMs != 0);
    m_cycle->setValue(canCycleMs ? canCycleMs : 20);
    m_cycle->setEnabled(canCycleMs != 0);
    connect(m_set, &QCheckBox::toggled, m_cycle, &QWidget::setEnabled);
    auto* row = new QHBoxLayout;
    row->addWidget(m_set);
    row->addWidget(m_cycle);
    row->addStretch();
    layout->addLayout(row);
    auto* note = new QLabel(tr("Unset, the unit keeps its default. The simulator sends a unit's "
                               "variables to the other units after every scan by default, and "
                               "with a cycle time set, once per cycle time."),
                            this);
    note->setWordWrap(true);
    note->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(note);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

int AdvancedSettingsDialog::canCycleMs() const {
    return m_set->isChecked() ? m_cycle->value() : 0;
}

} // namespace rs::ui
