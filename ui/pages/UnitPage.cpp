// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/UnitPage.h"

#include "blocks/UnitResources.h"
#include "document/PermissionNote.h"
#include "document/ProjectDocument.h"
#include "pages/AdvancedSettingsDialog.h"
#include "pages/ExternalCommDialog.h"
#include "pages/SignatureLabel.h"
#include "pages/UnitSettingsForm.h"
#include "project/CanBusCycle.h"
#include "project/ExportedVariables.h"
#include "project/ProjectGateways.h"
#include "project/RemanentVariables.h"
#include "project/UnitSettings.h"
#include "shell/PageTitle.h"
#include "shell/UnitCaption.h"

#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

namespace rs::ui {

namespace {

QString resourceText(const blocks::ResourceUse& use) {
    if (use.byBlocks == 0)
        return UnitPage::tr("%1 of %2").arg(use.used).arg(use.limit);
    return UnitPage::tr("%1 of %2 (%3 of them by block instances)")
        .arg(use.used)
        .arg(use.limit)
        .arg(use.byBlocks);
}

} // namespace

UnitPage::UnitPage(QWidget* parent)
    : QWidget(parent), m_title(new PageTitle(this)), m_form(new UnitSettingsForm(this)),
      m_undeclared(new QLabel(this)), m_exports(new QLabel(this)), m_remanent(new QLabel(this)),
      m_timers(new QLabel(this)), m_memories(new QLabel(this)), m_registers(new QLabel(this)),
      m_signature(new SignatureLabel(this)),
      m_remanentButton(new QPushButton(tr("&Remanent Variables..."), this)),
      m_canCycle(new QLabel(this)),
      m_advancedButton(new QPushButton(tr("&Advanced Settings..."), this)),
      m_externalComm(new QLabel(this)),
      m_externalCommButton(new QPushButton(tr("E&xternal Communication..."), this)) {
    m_undeclared->setWordWrap(true);
    m_undeclared->setText(tr("This unit has code but no '! id_pluto' declaration. Any change "
                             "below writes one."));
    m_exports->setObjectName(QStringLiteral("exportPairsLabel"));
    m_remanent->setObjectName(QStringLiteral("remanentLabel"));
    m_remanent->setWordWrap(true);
    m_remanentButton->setObjectName(QStringLiteral("remanentButton"));
    m_timers->setObjectName(QStringLiteral("timersUsedLabel"));
    m_memories->setObjectName(QStringLiteral("memoriesUsedLabel"));
    m_registers->setObjectName(QStringLiteral("registersUsedLabel"));

    auto* variables = new QGroupBox(tr("Variables on the bus and at power off"), this);
    auto* form = new QFormLayout(variables);
    form->addRow(tr("Export variables:"), m_exports);
    auto* remanentRow = new QHBoxLayout;
    remanentRow->addWidget(m_remanent, 1);
    remanentRow->addWidget(m_remanentButton);
    form->addRow(tr("Remanent variables:"), remanentRow);
    m_canCycle->setObjectName(QStringLiteral("canCycleLabel"));
    m_advancedButton->setObjectName(QStringLiteral("advancedSettingsButton"));
    auto* cycleRow = new QHBoxLayout;
    cycleRow->addWidget(m_canCycle, 1);
    cycleRow->addWidget(m_advancedButton);
    form->addRow(tr("CAN bus cycle time:"), cycleRow);
    m_externalComm->setObjectName(QStringLiteral("externalCommLabel"));
    m_externalComm->setWordWrap(true);
    m_externalCommButton->setObjectName(QStringLiteral("externalCommButton"));
    auto* externalRow = new QHBoxLayout;
    externalRow->addWidget(m_externalComm, 1);
    externalRow->addWidget(m_externalCommButton);
    form->addRow(tr("Gateway data received:"), externalRow);

    auto* resources = new QGroupBox(tr("Resources in use"), this);
    auto* resourceForm = new QFormLayout(resources);
    resourceForm->addRow(tr("Timers:"), m_timers);
    resourceForm->addRow(tr("Memories:"), m_memories);
    resourceForm->addRow(tr("Registers:"), m_registers);
    m_signature->setObjectName(QStringLiteral("unitSignature"));
    auto* review = new QGroupBox(tr("Review"), this);
    auto* reviewForm = new QFormLayout(review);
    reviewForm->addRow(tr("Program signature:"), m_signature);

    // Scrolled, so that the page does not make the window taller than a small screen.
    auto* content = new QWidget(this);
    auto* contentLayout = new QVBoxLayout(content);
    contentLayout->setContentsMargins(0, 0, 0, 0);
    contentLayout->addWidget(m_undeclared);
    contentLayout->addWidget(m_form);
    contentLayout->addWidget(variables);
    contentLayout->addWidget(resources);
    contentLayout->addWidget(review);
    contentLayout->addStretch();
    auto* scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(content);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addWidget(scroll, 1);

    connect(m_form, &UnitSettingsForm::edited, this, &UnitPage::apply);
    connect(m_remanentButton, &QPushButton::clicked, this,
            [this] { emit remanentRequested(m_document, m_station); });
    connect(m_advancedButton, &QPushButton::clicked, this, &UnitPage::editAdvancedSettings);
    connect(m_externalCommButton, &QPushButton::clicked, this, &UnitPage::editExternalComm);
}

void UnitPage::showUnit(ProjectDocument* document, int station) {
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    m_station = station;
    m_signature->setSource(document, station);
    if (!document)
        return;
    connect(document, &ProjectDocument::changed, this, &UnitPage::refresh);
    connect(document, &ProjectDocument::permissionChanged, this, &UnitPage::refresh);
    refresh();
}

void UnitPage::refresh() {
    if (!m_document)
        return;
    const project::Project& p = m_document->project();
    const auto unit = project::unitSettings(p, m_station);
    if (!unit)
        return;
    m_title->setTitle(unitCaption(*unit));
    const QString note = permissionNote(m_document->permission());
    m_title->setSubtitle(
        tr("Station %1 of project %2").arg(m_station).arg(QString::fromStdString(p.name())) +
        (note.isEmpty() ? QString() : QStringLiteral(" — ") + note));
    m_undeclared->setVisible(!unit->declared);
    m_form->setSettings(*unit, project::freeStations(p), true);
    if (unit->instructionSet < 3)
        m_exports->setText(tr("need instruction set 3"));
    else
        m_exports->setText(tr("%1 of %2 extra telegram pairs (project: %3 of %4)")
                               .arg(project::telegramPairs(p, m_station))
                               .arg(project::kTelegramPairsPerUnit)
                               .arg(project::telegramPairs(p))
                               .arg(project::kTelegramPairsPerProject));
    const target::UnitTypeInfo& type = target::unitTypeInfo(unit->type);
    const std::string remanent =
        project::formatRemanentList(project::remanentOf(p, m_station), m_station);
    m_remanent->setText(!type.remanent     ? tr("this type has none")
                        : remanent.empty() ? tr("none")
                                           : QString::fromStdString(remanent));
    const bool editable = m_document->permission() == project::Permission::Full;
    m_form->setEnabled(editable);
    m_remanentButton->setEnabled(type.remanent && editable);
    const int cycle = project::canCycleOf(p, m_station);
    m_canCycle->setText(cycle ? tr("%1 ms").arg(cycle) : tr("the unit's default"));
    m_advancedButton->setEnabled(editable);
    QStringList blocks;
    for (const auto& [block, setting] : project::externalCommOf(p, m_station))
        blocks << tr("block %1 from gateway %2, packet %3")
                      .arg(block)
                      .arg(setting.gateway)
                      .arg(setting.packet);
    m_externalComm->setText(blocks.isEmpty() ? tr("none") : blocks.join(QStringLiteral("; ")));
    m_externalCommButton->setEnabled(editable);
    const blocks::UnitResources resources = blocks::unitResources(p, m_station);
    m_timers->setText(resourceText(resources.timers));
    m_memories->setText(resourceText(resources.memories));
    m_registers->setText(resourceText(resources.registers));
}

void UnitPage::apply() {
    if (!m_document || !m_form->problem().isEmpty())
        return;
    const project::UnitSettings settings = m_form->settings();
    const auto current = project::unitSettings(m_document->project(), m_station);
    if (current && *current == settings)
        return;
    if (const int removed = project::removedByChange(m_document->project(), settings)) {
        const auto answer = QMessageBox::question(
            this, tr("Change Pluto %1").arg(m_station),
            tr("This removes %n declaration(s), name(s), description(s) or attribute(s) of the "
               "unit that the new type or instruction set cannot have. Change it?",
               nullptr, removed),
            QMessageBox::Yes | QMessageBox::No, QMessageBox::No);
        if (answer != QMessageBox::Yes) {
            refresh(); // the form shows the unit as it is again
            return;
        }
    }
    m_document->edit(tr("Change Pluto %1").arg(m_station),
                     [&](project::Project& p) { project::changeUnit(p, settings); });
}

void UnitPage::editExternalComm() {
    if (!m_document)
        return;
    ExternalCommDialog dialog(m_document->project(), m_station, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const int station = m_station;
    const project::ExternalComm setting = dialog.setting();
    if (setting == project::externalCommOf(m_document->project(), station))
        return;
    m_document->edit(tr("Set External Communication of Pluto %1").arg(station),
                     [&](project::Project& p) { project::setExternalComm(p, station, setting); });
}

void UnitPage::editAdvancedSettings() {
    if (!m_document)
        return;
    AdvancedSettingsDialog dialog(m_station, project::canCycleOf(m_document->project(), m_station),
                                  this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const int station = m_station;
    const int cycle = dialog.canCycleMs();
    m_document->edit(tr("Set CAN Bus Cycle Time of Pluto %1").arg(station),
                     [&](project::Project& p) { project::setCanCycle(p, station, cycle); });
}

} // namespace rs::ui
