// SPDX-License-Identifier: GPL-3.0-or-later
// The ladder page following the model: after a change of a run of one
// step's lines, only the networks it touches are read and laid out again;
// after any other change the unit's ladder is read again, an item laid out
// again only when its network changed; the items are placed one below the
// other.
#include "LadderPage.h"

#include "BlockText.h"
#include "LadderTool.h"
#include "LadderView.h"
#include "NetworkItem.h"
#include "StepHeaderItem.h"
#include "document/ProjectDocument.h"
#include "ladder/CursorNavigation.h"
#include "ladder/StepLineChange.h"
#include "ladder/UnitLadder.h"

#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>

#include <algorithm>
#include <span>

namespace rs::ui {

void LadderPage::followModel() {
    if (editSession()) {
        endEditSession();
        setMessage(tr("The project changed, so the network's edits were dropped."));
    }
    if (!followStepLines())
        rebuild();
    updateTitle();
}

bool LadderPage::followStepLines() {
    const auto& run = m_document ? m_document->changedStepLines() : std::nullopt;
    if (!run || m_pendingShown || m_undrawnLines > 0 || !m_blockStatuses.empty())
        return false;
    const lang::UnitProgram& unit = m_document->project().program.units.at(run->unit);
    if (unit.station() != m_station)
        return true; // another unit's code: nothing the page shows
    if (ladder::sequenceLines(unit, m_sequence) > ladder::kMostDrawnLines)
        return false;
    // The page's steps are the unit's steps of its sequence, in file order.
    std::size_t shown = 0;
    for (std::size_t s = 0; s < run->step; ++s)
        shown += unit.steps[s].address.sequence == m_sequence ? 1 : 0;
    const lang::Step& step = unit.steps.at(run->step);
    std::int64_t shift = 0;
    if (step.address.sequence == m_sequence) {
        if (shown >= m_steps.size())
            return false;
        const auto change = ladder::followLineChange(m_steps[shown], step, run->first, run->removed,
                                                     run->added.size());
        if (!change)
            return false;
        auto& items = m_items[shown];
        const auto at = [&](std::size_t index) {
            return items.begin() + static_cast<std::ptrdiff_t>(index);
        };
        for (auto item = at(change->first); item != at(change->first + change->removed); ++item)
            delete *item;
        items.erase(at(change->first), at(change->first + change->removed));
        items.insert(at(change->first), change->added, nullptr);
        const auto s = static_cast<int>(shown);
        for (std::size_t n = change->first; n < change->first + change->added; ++n)
            showNetwork(s, static_cast<int>(n));
        if (change->added != change->removed || change->statementShift != 0)
            for (std::size_t n = change->first + change->added; n < items.size(); ++n)
                renumberNetwork(s, static_cast<int>(n));
        shift = change->statementShift;
        ++shown;
    } else {
        const auto statements = [](std::span<const lang::Line> lines) {
            return std::count_if(lines.begin(), lines.end(), [](const lang::Line& line) {
                return std::holds_alternative<lang::Statement>(line.body);
            });
        };
        shift = statements(run->added) - statements(run->removed);
    }
    // The statements of the steps after it are numbered anew.
    for (std::size_t s = shown; shift != 0 && s < m_steps.size(); ++s) {
        ladder::StepPage& page = m_steps[s];
        page.firstStatement = static_cast<std::uint32_t>(page.firstStatement + shift);
        for (auto& first : page.firstStatements)
            first = static_cast<std::uint32_t>(first + shift);
        for (std::size_t n = 0; n < m_items[s].size(); ++n)
            renumberNetwork(static_cast<int>(s), static_cast<int>(n));
    }
    settleItems();
    return true;
}

namespace {

// Gives each network of a step its item: networks inserted or removed in
// the middle leave the items after them with their networks (to be
// numbered anew, not laid out again); the rest are kept by place. Places
// left without an item are null.
void keepItemsWithTheirNetworks(std::vector<NetworkItem*>& items,
                                const std::vector<ladder::Network>& networks) {
    const std::size_t before = items.size();
    const std::size_t after = networks.size();
    const std::size_t shorter = std::min(before, after);
    std::size_t prefix = 0;
    while (prefix < shorter && items[prefix]->network() == networks[prefix])
        ++prefix;
    std::size_t suffix = 0;
    while (before != after && suffix < shorter - prefix &&
           items[before - 1 - suffix]->network() == networks[after - 1 - suffix])
        ++suffix;
    std::vector<NetworkItem*> kept(after, nullptr);
    std::copy(items.begin(), items.begin() + static_cast<std::ptrdiff_t>(prefix), kept.begin());
    std::copy(items.end() - static_cast<std::ptrdiff_t>(suffix), items.end(),
              kept.end() - static_cast<std::ptrdiff_t>(suffix));
    // Between them, by place, as many as both have; the other old ones go.
    for (std::size_t i = prefix; i < before - suffix; ++i) {
        if (i < after - suffix)
            kept[i] = items[i];
        else
            delete items[i];
    }
    items = std::move(kept);
}

} // namespace

void LadderPage::rebuild() {
    m_steps.clear();
    m_stepComments.clear();
    m_undrawnLines = 0;
    m_pendingShown = false;
    m_blockStatuses.clear();
    if (m_document) {
        const project::Project& project = m_document->project();
        std::vector<lang::Line> names = project.program.preamble;
        for (const auto& unit : project.program.units) {
            if (unit.station() != m_station)
                continue;
            names.insert(names.end(), unit.declarations.begin(), unit.declarations.end());
            if (const std::size_t lines = ladder::sequenceLines(unit, m_sequence);
                lines > ladder::kMostDrawnLines) {
                m_undrawnLines = lines;
                continue;
            }
            m_blockStatuses =
                blocks::instanceStatuses(project.program, m_station, m_document->libraries());
            // Edited by hand, an instance is its statements (drawnAsBox).
            const auto shown = [this](const lang::Step& step, const blocks::BlockInstance& found) {
                const auto* status = blocks::statusAt(m_blockStatuses, step.address, found.record);
                return status && blocks::drawnAsBox(*status);
            };
            for (auto& page : ladder::unitLadder(unit, shown))
                if (page.address.sequence == m_sequence)
                    m_steps.push_back(std::move(page));
            for (const auto& step : unit.steps)
                if (step.address.sequence == m_sequence)
                    m_stepComments.push_back(
                        QString::fromStdString(step.comment.value_or(std::string())).trimmed());
        }
        if (names != m_names || m_namesVersion == 0) {
            m_names = std::move(names);
            m_symbols = ladder::SymbolTable::of(project.program, m_station);
            ++m_namesVersion;
        }
    }
    if (m_undrawnLines > 0) {
        m_steps.clear();
        m_stepComments.clear();
        m_pending.reset();
    } else if (m_steps.empty() && m_document && m_sequence == 0) {
        m_steps.push_back({{m_station, 0, 0}, {}, {}, 0});
        m_stepComments.emplace_back();
    }
    if (m_pending) {
        auto [step, index] = *m_pending;
        if (step < stepCount() && index <= networkCount(step)) {
            auto& page = m_steps[step];
            const std::uint32_t first =
                index < networkCount(step) ? page.firstStatements[index]
                : index > 0                ? page.firstStatements[index - 1] +
                                  ladder::statementCount(page.ladder.networks[index - 1])
                            : 0;
            page.ladder.networks.insert(page.ladder.networks.begin() + index, ladder::Network{});
            page.firstStatements.insert(page.firstStatements.begin() + index, first);
            m_pendingShown = true;
        } else {
            m_pending.reset();
        }
    }

    // Items are kept by place; an item lays out again only when its network changed.
    while (m_items.size() > m_steps.size()) {
        for (NetworkItem* item : m_items.back())
            delete item;
        m_items.pop_back();
        delete m_headers.back();
        m_headers.pop_back();
    }
    for (std::size_t s = 0; s < m_steps.size(); ++s) {
        const auto& page = m_steps[s];
        const QString stepText =
            QStringLiteral("%1   %2   %3")
                .arg(tr("Step %1").arg(page.address.step),
                     QString::fromStdString(lang::toString(page.address)), m_stepComments[s]);
        if (s >= m_items.size()) {
            m_items.emplace_back();
            m_headers.push_back(
                new StepHeaderItem(&m_drawing, m_sequence, page.address.step, stepText));
            m_scene->addItem(m_headers.back());
        }
        m_headers[s]->setText(page.address.step, stepText.trimmed());
        m_headers[s]->setVisible(m_sequence != 0);
        keepItemsWithTheirNetworks(m_items[s], page.ladder.networks);
        for (int n = 0; n < static_cast<int>(page.ladder.networks.size()); ++n)
            showNetwork(static_cast<int>(s), n);
    }
    settleItems();
}

ladder::LayoutContext LadderPage::layoutContext(int step, int network) const {
    ladder::LayoutContext context;
    context.number = network + 1;
    context.title = tr("Network %1").arg(network + 1);
    context.firstStatement = m_steps[step].firstStatements[network];
    context.symbols = &m_symbols;
    if (const blocks::InstanceStatus* status = blockStatus(step, network)) {
        context.block = status->block;
        context.language = BlockText::descriptionLanguage();
        context.blockNote = blockNote(*status);
    }
    return context;
}

void LadderPage::showNetwork(int step, int network) {
    NetworkItem*& item = m_items[step][network];
    if (!item) {
        item = new NetworkItem(&m_drawing, step, network);
        m_scene->addItem(item);
    }
    item->setIndex(step, network);
    item->setNetwork(m_steps[step].ladder.networks[network], layoutContext(step, network),
                     m_namesVersion);
}

void LadderPage::renumberNetwork(int step, int network) {
    NetworkItem* item = m_items[step][network];
    item->setIndex(step, network);
    item->renumber(layoutContext(step, network));
}

void LadderPage::settleItems() {
    placeItems();
    // The cursor stays where it was while that place exists.
    LadderCursor& cursor = m_drawing.cursor;
    if (cursor.valid() &&
        (cursor.step >= stepCount() || cursor.network >= networkCount(cursor.step)))
        cursor = {};
    else if (cursor.valid() && !cursor.wholeNetwork() && !cursorElement() &&
             !(cursor.node &&
               ladder::nodeAt(m_steps[cursor.step].ladder.networks[cursor.network], *cursor.node)))
        cursor = {cursor.step, cursor.network, std::nullopt, std::nullopt, -1};
    updateActions();
    repaintItems();
}

void LadderPage::placeItems() {
    qreal y = 0;
    qreal width = 400;
    for (std::size_t s = 0; s < m_items.size(); ++s) {
        if (m_headers[s]->isVisible()) {
            m_headers[s]->setPos(0, y);
            y += StepHeaderItem::kHeight + kNetworkGap;
        }
        for (NetworkItem* item : m_items[s]) {
            if (item->pos() != QPointF(0, y))
                item->setPos(0, y);
            const QRectF bounds = item->boundingRect();
            y += bounds.height() + kNetworkGap;
            width = std::max(width, bounds.width());
        }
    }
    for (StepHeaderItem* header : m_headers)
        header->setWidth(width);
    // An empty page says how to begin.
    const bool empty =
        std::all_of(m_items.begin(), m_items.end(), [](const auto& step) { return step.empty(); });
    m_emptyHint->setVisible(empty && m_document);
    m_emptyHint->setText(
        m_undrawnLines > 0
            ? tr("This code has %1 lines, more than the ladder page draws (%2).\nIts text page "
                 "(F6) shows and edits it.")
                  .arg(m_undrawnLines)
                  .arg(ladder::kMostDrawnLines)
        : isLive() ? tr("No networks in this code.")
                   : m_editingHint);
    m_emptyHint->setBrush(m_drawing.style.commentInk);
    m_emptyHint->setPos(NetworkItem::kGutter, y + 16);
    if (empty)
        y += 60;
    m_scene->setSceneRect(0, 0, width, std::max<qreal>(y, 1));
}

void LadderPage::repaintItems() {
    m_view->viewport()->update();
}

int LadderPage::networkCount(int step) const {
    return step >= 0 && step < stepCount() ? static_cast<int>(m_steps[step].ladder.networks.size())
                                           : 0;
}

NetworkItem* LadderPage::networkItem(int step, int network) const {
    if (step < 0 || step >= static_cast<int>(m_items.size()) || network < 0 ||
        network >= static_cast<int>(m_items[step].size()))
        return nullptr;
    return m_items[step][network];
}

void LadderPage::setAllCollapsed(bool collapsed) {
    for (auto& step : m_items)
        for (NetworkItem* item : step)
            item->setCollapsed(collapsed);
    placeItems();
    repaintItems();
}

void LadderPage::toggleCollapsed(int step, int network) {
    if (NetworkItem* item = networkItem(step, network)) {
        item->setCollapsed(!item->collapsed());
        placeItems();
        repaintItems();
    }
}

} // namespace rs::ui
