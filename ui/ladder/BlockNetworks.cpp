// SPDX-License-Identifier: GPL-3.0-or-later
// Block networks on a ladder page (blocks.md): inserting an instance of a
// library block, binding its pins, and bringing it up to its block's
// current version. Each is one undo step; the statements of the instance
// are written by expanding it as reading the project does, so what the page
// makes is what a file written by hand with the same record would give.
#include "LadderPage.h"

#include "BlockChooserDialog.h"
#include "BlockDocumentationDialog.h"
#include "BlockPinsDialog.h"
#include "BlockText.h"
#include "MakeBlockDialog.h"
#include "NetworkItem.h"
#include "blocks/LibrarySearch.h"
#include "blocks/ProjectInstances.h"
#include "blocks/UserLibraryFile.h"
#include "document/ProjectDocument.h"
#include "ladder/LadderToText.h"
#include "project/UnitSettings.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QMessageBox>
#include <QRegularExpression>

#include <algorithm>

namespace rs::ui {

const blocks::InstanceStatus* LadderPage::blockStatus(int step, int network) const {
    if (step < 0 || step >= stepCount() || network < 0 || network >= networkCount(step))
        return nullptr;
    const auto& block = m_steps[step].ladder.networks[network].block;
    if (!block)
        return nullptr;
    return blocks::statusAt(m_blockStatuses, m_steps[step].address, block->instance.record);
}

QString LadderPage::blockNote(const blocks::InstanceStatus& status) const {
    if (status.standing != blocks::Standing::OtherVersion || !status.block)
        return {};
    return tr("Made by %1 version %2; the library has version %3 (Update Block).")
        .arg(QString::fromStdString(status.instance.type),
             QString::fromStdString(status.instance.version),
             QString::fromStdString(status.block->version));
}

std::set<lang::Address> LadderPage::pinVariables() const {
    std::set<lang::Address> variables;
    for (const auto& step : m_items)
        for (const NetworkItem* item : step)
            if (const auto& block = item->layout().block)
                for (const auto& pin : block->pins)
                    if (pin.address)
                        variables.insert(*pin.address);
    return variables;
}

void LadderPage::insertBlock() {
    if (!editable())
        return;
    updateNetwork();
    if (stepCount() == 0) {
        setMessage(tr("This sequence has no step yet."));
        return;
    }
    BlockChooserDialog chooser(m_document->libraries(), this);
    if (chooser.exec() != QDialog::Accepted || !chooser.block())
        return;
    const blocks::BlockDefinition block = *chooser.block();
    blocks::BlockInstance instance;
    instance.type = block.name;
    instance.library = chooser.library()->library.name;
    BlockPinsDialog pins(m_document, m_station, block, instance, this);
    if (pins.exec() != QDialog::Accepted || !pins.instance())
        return;

    int step = m_drawing.cursor.valid() ? m_drawing.cursor.step : stepCount() - 1;
    int index = m_drawing.cursor.valid() ? m_drawing.cursor.network + 1 : networkCount(step);
    ladder::StepLadder ladder = m_steps[step].ladder;
    if (m_pending) {
        // The new network waiting for its first rung becomes the block's.
        std::tie(step, index) = *m_pending;
        ladder = m_steps[step].ladder;
        ladder.networks.erase(ladder.networks.begin() + index);
        m_pending.reset();
    }
    index = std::min(index, static_cast<int>(ladder.networks.size()));
    ladder::Network network;
    network.block = ladder::unexpandedCall(*pins.instance());
    ladder.networks.insert(ladder.networks.begin() + index, std::move(network));
    commitStep(tr("Insert Block %1").arg(QString::fromStdString(block.name)), step,
               std::move(ladder));
    setCursor({step, index, std::nullopt, std::nullopt, -1});
}

void LadderPage::editBlockPins(int step, int network) {
    if (!editable())
        return;
    const blocks::InstanceStatus* status = blockStatus(step, network);
    if (!status || !status->block) {
        setMessage(tr("No library of the project has this block: add its library on the project "
                      "page to bind its pins."));
        return;
    }
    updateNetwork();
    const blocks::BlockDefinition block = *status->block;
    BlockPinsDialog dialog(m_document, m_station, block, status->instance, this);
    if (dialog.exec() != QDialog::Accepted || !dialog.instance() ||
        blocks::recordText(*dialog.instance()) == blocks::recordText(status->instance))
        return;
    rewriteBlock(tr("Change Block Pins"), step, network, *dialog.instance());
}

void LadderPage::updateBlock() {
    if (!editable())
        return;
    const LadderCursor cursor = m_drawing.cursor;
    const blocks::InstanceStatus* status = blockStatus(cursor.step, cursor.network);
    if (!status || status->standing != blocks::Standing::OtherVersion) {
        setMessage(tr("Select a block made by another version of its block to update it."));
        return;
    }
    updateNetwork();
    blocks::BlockInstance instance = status->instance;
    instance.version.clear();
    rewriteBlock(tr("Update Block %1").arg(QString::fromStdString(instance.type)), cursor.step,
                 cursor.network, std::move(instance));
}

void LadderPage::showBlockDocumentation() {
    const blocks::InstanceStatus* status =
        blockStatus(m_drawing.cursor.step, m_drawing.cursor.network);
    if (!status || !status->block) {
        setMessage(tr("Select a block network whose block a library of the project has."));
        return;
    }
    BlockDocumentationDialog::show(*status->library, *status->block, this);
}

void LadderPage::makeBlock() {
    if (!editable())
        return;
    updateNetwork();
    std::vector<std::pair<int, int>> chosen = chosenNetworks();
    std::sort(chosen.begin(), chosen.end());
    if (chosen.empty())
        return;
    const int step = chosen.front().first;
    ladder::StepLadder made;
    ladder::StepLadder rest = m_steps[step].ladder;
    for (auto it = chosen.rbegin(); it != chosen.rend(); ++it) {
        if (it->first != step || it->second >= networkCount(step)) {
            setMessage(tr("Make Block takes networks of one step."));
            return;
        }
        const ladder::Network& network = rest.networks[it->second];
        if (network.block) {
            setMessage(tr("A block cannot hold a block: leave block networks out of the "
                          "selection."));
            return;
        }
        made.networks.insert(made.networks.begin(), network);
        rest.networks.erase(rest.networks.begin() + it->second);
    }
    if (m_document->path().isEmpty()) {
        setMessage(tr("Save the project first: its blocks go to a library beside it."));
        return;
    }
    // What the rest of the unit's code uses stays outside the block.
    std::vector<lang::Line> elsewhere = ladder::toLines(rest);
    for (const auto& unit : m_document->project().program.units)
        if (unit.station() == m_station)
            for (const auto& unitStep : unit.steps)
                if (!(unitStep.address == m_steps[step].address))
                    elsewhere.insert(elsewhere.end(), unitStep.lines.begin(), unitStep.lines.end());

    const QDir folder = QFileInfo(m_document->path()).absoluteDir();
    QStringList files = QDir(folder).entryList(
        {QStringLiteral("*.") + QLatin1String(blocks::kLibraryExtension)}, QDir::Files, QDir::Name);
    QString stem = QFileInfo(m_document->path()).completeBaseName();
    stem.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9_]")), QStringLiteral("_"));
    const QString offered = QStringLiteral("%1_Blocks.%2").arg(stem, blocks::kLibraryExtension);
    if (!files.contains(offered))
        files.prepend(offered);
    MakeBlockDialog dialog(ladder::toLines(made), blocks::addressesIn(elsewhere), files, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const blocks::BlockDraft& draft = dialog.draft();
    const QString file = folder.absoluteFilePath(dialog.libraryFile());
    if (const QString error =
            blocks::addBlockToLibraryFile(file, draft.block, dialog.newLibraryName());
        !error.isEmpty()) {
        QMessageBox::warning(this, tr("Make Block"),
                             tr("The block could not be written: %1").arg(error));
        return;
    }
    m_document->reloadLibraries();

    // The project names its libraries only when it chose them; then it names this one too.
    std::vector<std::string> entries = m_document->project().libraries;
    const std::string entry = dialog.libraryFile().toStdString();
    if (!entries.empty() && std::find(entries.begin(), entries.end(), entry) == entries.end())
        entries.push_back(entry);
    const blocks::LibrarySet libraries = blocks::librariesFor(
        {QCoreApplication::applicationDirPath(), m_document->path(), {}}, entries);
    const blocks::LoadedLibrary* library = nullptr;
    for (const auto& loaded : libraries.libraries)
        if (loaded.path == file)
            library = &loaded;
    if (!library) {
        setMessage(tr("The library %1 is not among the project's libraries.").arg(file));
        return;
    }
    blocks::BlockInstance instance = draft.instance;
    instance.library = library->library.name;
    ladder::Network network;
    network.block = ladder::unexpandedCall(std::move(instance));
    const int at = chosen.front().second;
    rest.networks.insert(rest.networks.begin() + at, std::move(network));
    const lang::StepAddress address = m_steps[step].address;
    const int station = m_station;
    m_drawing.marked.clear();
    m_document->edit(tr("Make Block %1").arg(QString::fromStdString(draft.block.name)),
                     [&](project::Project& p) {
                         p.libraries = entries;
                         ladder::setStepLadder(project::programOf(p, station), address, rest);
                         blocks::expandInstances(p.program, libraries);
                     });
    setCursor({step, at, std::nullopt, std::nullopt, -1});
    setMessage(tr("Block %1 is in %2; the F list offers it.")
                   .arg(QString::fromStdString(draft.block.name), QDir::toNativeSeparators(file)));
}

void LadderPage::rewriteBlock(const QString& name, int step, int network,
                              blocks::BlockInstance instance) {
    ladder::StepLadder ladder = m_steps[step].ladder;
    ladder::Network& written = ladder.networks[network];
    std::vector<ladder::NetworkItem> after = std::move(written.items);
    written = {};
    written.block = ladder::unexpandedCall(std::move(instance));
    written.items = std::move(after);
    commitStep(name, step, std::move(ladder));
    setCursor({step, network, std::nullopt, std::nullopt, -1});
}

} // namespace rs::ui
