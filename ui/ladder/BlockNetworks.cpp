// SPDX-License-Identifier: GPL-3.0-or-later
// Block networks on a ladder page (blocks.md): inserting an instance of a
// library block, binding its pins, and bringing it up to its block's
// current version. Each is one undo step; the statements of the instance
// are written by expanding it as reading the project does, so what the page
// makes is what a file written by hand with the same record would give.
#include "LadderPage.h"

#include "BlockChooserDialog.h"
#include "BlockPinsDialog.h"
#include "BlockText.h"
#include "NetworkItem.h"
#include "document/ProjectDocument.h"

namespace rs::ui {

namespace {

QString fromUtf8(const std::string& text) {
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

} // namespace

const blocks::InstanceStatus* LadderPage::blockStatus(int step, int network) const {
    if (step < 0 || step >= stepCount() || network < 0 || network >= networkCount(step))
        return nullptr;
    const auto& block = m_steps[step].ladder.networks[network].block;
    if (!block)
        return nullptr;
    for (const auto& status : m_blockStatuses)
        if (status.address == m_steps[step].address &&
            status.instance.record == block->instance.record)
            return &status;
    return nullptr;
}

QString LadderPage::blockNote(const blocks::InstanceStatus& status) const {
    if (status.standing != blocks::Standing::OtherVersion || !status.block)
        return {};
    return tr("Made by %1 version %2; the library has version %3 (Update Block).")
        .arg(fromUtf8(status.instance.type), fromUtf8(status.instance.version),
             fromUtf8(status.block->version));
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
    commitStep(tr("Insert Block %1").arg(fromUtf8(block.name)), step, std::move(ladder));
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
    rewriteBlock(tr("Update Block %1").arg(fromUtf8(instance.type)), cursor.step, cursor.network,
                 std::move(instance));
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
