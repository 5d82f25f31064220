// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/UnitCommands.h"

#include "document/ProjectDocument.h"
#include "document/ProjectPaths.h"
#include "pages/CsvExportDialog.h"
#include "pages/CsvImportDialog.h"
#include "pages/NewUnitDialog.h"
#include "pages/RemanentDialog.h"
#include "project/ProjectFile.h"
#include "project/RemanentVariables.h"
#include "project/Sequences.h"
#include "project/UnitSettings.h"
#include "project/VariableCsv.h"
#include "shell/NamedIcon.h"
#include "shell/UnitCaption.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QInputDialog>
#include <QMessageBox>

namespace rs::ui {

UnitCommands::UnitCommands(QWidget* window, std::function<PageRef()> current)
    : QObject(window), m_window(window), m_current(std::move(current)) {
    createActions();
}

void UnitCommands::createActions() {
    const auto action = [this](const QString& text, const char* name) {
        auto* created = new QAction(text, m_window);
        created->setObjectName(QString::fromLatin1(name));
        return created;
    };
    // The unit of the page shown; none on the project's own pages.
    const auto onUnit = [this](void (UnitCommands::*command)(ProjectDocument*, int)) {
        return [this, command] {
            const PageRef current = m_current();
            (this->*command)(current.document, current.station);
        };
    };

    m_actions.newUnit = action(tr("New &Pluto..."), "newUnitAction");
    m_actions.newUnit->setIcon(namedIcon("unit-new"));
    m_actions.newUnit->setStatusTip(tr("Add a Pluto unit to the project"));
    connect(m_actions.newUnit, &QAction::triggered, this,
            [this] { newUnit(m_current().document); });
    m_actions.newSequence = action(tr("New &Sequence..."), "newSequenceAction");
    connect(m_actions.newSequence, &QAction::triggered, this, onUnit(&UnitCommands::newSequence));
    m_actions.removeUnit = action(tr("&Remove Pluto..."), "removeUnitAction");
    connect(m_actions.removeUnit, &QAction::triggered, this, onUnit(&UnitCommands::removeUnit));
    m_actions.remanent = action(tr("Re&manent Variables..."), "remanentAction");
    connect(m_actions.remanent, &QAction::triggered, this, onUnit(&UnitCommands::editRemanent));
    m_actions.importCsv = action(tr("&Import Variable Names (CSV)..."), "importCsvAction");
    m_actions.importCsv->setIcon(namedIcon("import"));
    connect(m_actions.importCsv, &QAction::triggered, this, onUnit(&UnitCommands::importCsv));
    m_actions.exportCsv = action(tr("E&xport Variable Names (CSV)..."), "exportCsvAction");
    m_actions.exportCsv->setIcon(namedIcon("export"));
    connect(m_actions.exportCsv, &QAction::triggered, this, onUnit(&UnitCommands::exportCsv));
}

void UnitCommands::updateActions(const PageRef& current) {
    const ProjectDocument* document = current.document;
    const bool healthy = document && !document->isDamaged();
    const bool inUnit = healthy && current.station >= 0 &&
                        project::unitSettings(document->project(), current.station).has_value();
    // Password protected without full permission: what changes the project is not offered.
    const bool writable = healthy && document->permission() == project::Permission::Full;
    m_actions.newUnit->setEnabled(writable && !project::freeStations(document->project()).empty());
    m_actions.newSequence->setEnabled(inUnit && writable);
    m_actions.removeUnit->setEnabled(inUnit && writable);
    m_actions.remanent->setEnabled(
        inUnit && writable && project::unitTypeOf(document->project(), current.station).remanent);
    m_actions.importCsv->setEnabled(inUnit && writable);
    m_actions.exportCsv->setEnabled(inUnit);
}

void UnitCommands::newUnit(ProjectDocument* document) {
    if (!document || document->isDamaged())
        return;
    if (project::freeStations(document->project()).empty()) {
        QMessageBox::information(m_window, tr("New Pluto"),
                                 tr("The project has 32 units, the most a bus can have."));
        return;
    }
    NewUnitDialog dialog(document->project(), m_window);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const project::UnitSettings settings = dialog.settings();
    QString refusal;
    document->edit(tr("New Pluto %1").arg(settings.station), [&](project::Project& p) {
        if (auto problem = project::addUnit(p, settings))
            refusal = QString::fromStdString(*problem);
    });
    if (!refusal.isEmpty()) {
        QMessageBox::warning(m_window, tr("New Pluto"), refusal);
        return;
    }
    emit unitAdded(document, settings.station);
}

void UnitCommands::newSequence(ProjectDocument* document, int station) {
    if (!document || station < 0)
        return;
    const std::vector<int> free = project::freeSequences(document->project(), station);
    if (free.empty()) {
        QMessageBox::information(m_window, tr("New Sequence"),
                                 tr("Pluto %1 has all nine sequences.").arg(station));
        return;
    }
    QStringList choices;
    for (int sequence : free)
        choices << QString::number(sequence);
    bool ok = false;
    const QString chosen = QInputDialog::getItem(
        m_window, tr("New Sequence"), tr("Sequence number for Pluto %1 (1-9):").arg(station),
        choices, 0, false, &ok);
    if (!ok)
        return;
    const int sequence = chosen.toInt();
    document->edit(tr("New Sequence %1 of Pluto %2").arg(sequence).arg(station),
                   [&](project::Project& p) { project::addSequence(p, station, sequence); });
    emit sequenceAdded(document, station, sequence);
}

void UnitCommands::removeUnit(ProjectDocument* document, int station) {
    if (!document || !project::unitSettings(document->project(), station))
        return;
    const auto answer = QMessageBox::question(
        m_window, tr("Remove Pluto"),
        tr("Remove %1 with its code, names and descriptions from the project? Edit > Undo brings "
           "it back.")
            .arg(unitCaption(document->project(), station)));
    if (answer != QMessageBox::Yes)
        return;
    emit unitRemoving(document, station);
    document->edit(tr("Remove Pluto %1").arg(station),
                   [&](project::Project& p) { project::removeUnit(p, station); });
}

void UnitCommands::editRemanent(ProjectDocument* document, int station) {
    if (!document || !project::unitTypeOf(document->project(), station).remanent)
        return;
    RemanentDialog dialog(station, project::remanentOf(document->project(), station), m_window);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const std::set<lang::Address> selection = dialog.selection();
    QString refusal;
    document->edit(tr("Set Remanent Variables of Pluto %1").arg(station), [&](project::Project& p) {
        if (auto problem = project::setRemanent(p, station, selection))
            refusal = QString::fromStdString(*problem);
    });
    if (!refusal.isEmpty())
        QMessageBox::warning(m_window, tr("Remanent Variables"), refusal);
}

void UnitCommands::importCsv(ProjectDocument* document, int station) {
    if (!document)
        return;
    CsvImportDialog dialog(document->project(), station, m_window);
    if (dialog.exec() != QDialog::Accepted)
        return;
    document->replace(tr("Import Variable Names to Pluto %1").arg(station),
                      dialog.result().project);
    emit message(
        tr("Imported %n variable(s).", nullptr, static_cast<int>(dialog.result().changes.size())));
}

void UnitCommands::exportCsv(ProjectDocument* document, int station) {
    if (!document)
        return;
    const QFileInfo base(suggestedPath(*document));
    CsvExportDialog dialog(
        station,
        base.dir().filePath(
            QStringLiteral("%1-pluto%2.csv").arg(base.completeBaseName()).arg(station)),
        m_window);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const std::string csv = project::exportVariablesCsv(document->project(), dialog.options());
    const QString error = project::writeTextFile(dialog.path(), csv);
    if (!error.isEmpty()) {
        QMessageBox::critical(m_window, tr("Export Variable Names"), error);
        return;
    }
    emit message(tr("Wrote %1").arg(QDir::toNativeSeparators(dialog.path())));
}

} // namespace rs::ui
