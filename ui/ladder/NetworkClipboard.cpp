// SPDX-License-Identifier: GPL-3.0-or-later
// Whole networks of a ladder page to and from the clipboard, and deleted:
// the networks marked with Ctrl or Shift and a click, or the selected one.
#include "LadderPage.h"

#include "LadderTool.h"
#include "document/ProjectDocument.h"
#include "ladder/NetworkText.h"

#include <QApplication>
#include <QClipboard>
#include <QMimeData>

#include <algorithm>

namespace rs::ui {

namespace {

constexpr char kNetworksMimeType[] = "application/x-rungsmith-networks";

} // namespace

std::vector<std::pair<int, int>> LadderPage::chosenNetworks() const {
    std::vector<std::pair<int, int>> chosen(m_drawing.marked.begin(), m_drawing.marked.end());
    const LadderCursor& cursor = m_drawing.cursor;
    if (chosen.empty() && cursor.valid())
        chosen.emplace_back(cursor.step, cursor.network);
    return chosen;
}

void LadderPage::copyNetworks() {
    std::vector<ladder::Network> networks;
    for (auto [step, network] : chosenNetworks()) {
        if (network >= networkCount(step))
            continue;
        const ladder::Network& chosen = m_steps[step].ladder.networks[network];
        if (!chosen.items.empty() || chosen.block)
            networks.push_back(chosen);
    }
    if (networks.empty())
        return;
    const QByteArray text = QByteArray::fromStdString(ladder::networksText(networks));
    auto* data = new QMimeData;
    data->setData(QLatin1String(kNetworksMimeType), text);
    data->setText(QString::fromUtf8(text));
    QApplication::clipboard()->setMimeData(data);
    setMessage(tr("%n network(s) copied.", nullptr, static_cast<int>(networks.size())));
}

void LadderPage::cutNetworks() {
    copyNetworks();
    deleteNetworks();
}

void LadderPage::pasteNetworks() {
    if (!editable() || stepCount() == 0)
        return;
    const QMimeData* data = QApplication::clipboard()->mimeData();
    if (!data)
        return;
    const QByteArray text = data->hasFormat(QLatin1String(kNetworksMimeType))
                                ? data->data(QLatin1String(kNetworksMimeType))
                                : data->text().toUtf8();
    ladder::NetworksReading read = ladder::readNetworksText(text.toStdString());
    if (!read.error.empty() || read.networks.empty()) {
        setMessage(read.error.empty() ? tr("The clipboard holds no networks.")
                                      : tr("The clipboard holds no networks: %1")
                                            .arg(QString::fromStdString(read.error)));
        return;
    }
    const LadderCursor cursor = m_drawing.cursor;
    const int step = cursor.valid() ? cursor.step : stepCount() - 1;
    const int index = cursor.valid() ? cursor.network + 1 : networkCount(step);
    const auto count = static_cast<int>(read.networks.size());
    if (m_pending && m_pending->first == step && m_pending->second >= index)
        m_pending->second += count;
    commitNetworks(tr("Paste %n Network(s)", nullptr, count), step, index, 0,
                   std::move(read.networks));
    m_drawing.marked.clear();
    for (int n = index; n < index + count && n < networkCount(step); ++n)
        m_drawing.marked.insert({step, n});
    setCursor({step, std::min(index, networkCount(step) - 1), std::nullopt, std::nullopt, -1});
}

void LadderPage::deleteNetworks() {
    if (!editable())
        return;
    std::vector<std::pair<int, int>> chosen = chosenNetworks();
    if (chosen.empty())
        return;
    undoNetwork();
    std::sort(chosen.begin(), chosen.end());
    const int step = chosen.front().first;
    std::erase_if(chosen, [&](const std::pair<int, int>& c) {
        return c.first != step || c.second >= networkCount(step);
    });
    if (chosen.empty())
        return;
    const int first = chosen.front().second;
    const auto removed = static_cast<int>(chosen.size());
    // The network the page holds alone goes without an undo step.
    const bool pendingRemoved =
        m_pending && std::find(chosen.begin(), chosen.end(), *m_pending) != chosen.end();
    if (pendingRemoved)
        m_pending.reset();
    m_drawing.marked.clear();
    const QString name = tr("Delete %n Network(s)", nullptr, removed);
    if (removed > 0 && chosen.back().second - first + 1 == removed) {
        commitNetworks(name, step, first, removed, {});
    } else {
        ladder::StepLadder ladder = m_steps[step].ladder;
        for (auto it = chosen.rbegin(); it != chosen.rend(); ++it)
            ladder.networks.erase(ladder.networks.begin() + it->second);
        commitStep(name, step, std::move(ladder));
    }
    if (pendingRemoved)
        rebuild();
    if (networkCount(step) > 0)
        setCursor({step, std::min(first, networkCount(step) - 1), std::nullopt, std::nullopt, -1});
    else
        setCursor({});
}

} // namespace rs::ui
