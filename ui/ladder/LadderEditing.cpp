// SPDX-License-Identifier: GPL-3.0-or-later
// The editing commands of a ladder page: each goes through the ladder
// model's editing operations (core/ladder/Editing.h) and becomes one undo
// step of the project, or in a network's edit mode a change of the page's
// copy of that network until Update or Undo.
#include "LadderPage.h"

#include "ConfigOptionDialog.h"
#include "ElementDialog.h"
#include "LadderActions.h"
#include "LadderTool.h"
#include "NetworkCommentDialog.h"
#include "NetworkEditTool.h"
#include "NetworkItem.h"
#include "blocks/ProjectInstances.h"
#include "document/ProjectDocument.h"
#include "ladder/CursorNavigation.h"
#include "ladder/LadderToText.h"
#include "project/Sequences.h"
#include "project/UnitSettings.h"
#include "project/UnitText.h"

#include <QInputDialog>
#include <QLineEdit>

#include <algorithm>

namespace rs::ui {

namespace {

QString signatureOf(const ladder::ElementLayout& element) {
    return QStringLiteral("%1|%2|%3|%4|%5")
        .arg(static_cast<int>(element.kind))
        .arg(element.name, element.address, element.text)
        .arg(element.output >= 0);
}

std::vector<QString> signaturesOf(const ladder::NetworkLayout& layout) {
    std::vector<QString> signatures;
    for (const auto& element : layout.elements)
        signatures.push_back(signatureOf(element));
    return signatures;
}

} // namespace

bool LadderPage::editNetwork(const QString& name, int step, int network,
                             const std::function<ladder::EditResult(ladder::Network&)>& edit) {
    if (step < 0 || step >= stepCount() || network < 0 || network >= networkCount(step))
        return false;
    NetworkItem* item = networkItem(step, network);
    const std::vector<QString> before = signaturesOf(item->layout());
    ladder::Network edited = m_steps[step].ladder.networks[network];
    const ladder::EditResult result = edit(edited);
    if (!result.done()) {
        setMessage(tr("Not done: %1").arg(QString::fromStdString(result.refusal)));
        return false;
    }
    setMessage({});
    if (const EditSession* session = editSession();
        session && session->step == step && session->network == network) {
        m_steps[step].ladder.networks[network] = std::move(edited);
        showNetwork(step, network);
        placeItems();
    } else {
        commitNetworks(name, step, network, 1, {std::move(edited)});
    }
    selectAdded(step, network, before);
    return true;
}

std::optional<std::size_t> LadderPage::unitStepIndex(int step) const {
    if (step < 0 || step >= stepCount())
        return std::nullopt;
    const auto& units = m_document->project().program.units;
    for (const auto& unit : units) {
        if (unit.station() != m_station)
            continue;
        int shown = 0;
        for (std::size_t s = 0; s < unit.steps.size(); ++s)
            if (unit.steps[s].address.sequence == m_sequence && shown++ == step)
                return unit.steps[s].address == m_steps[step].address
                           ? std::optional<std::size_t>(s)
                           : std::nullopt;
    }
    return std::nullopt;
}

void LadderPage::commitNetworks(const QString& name, int step, int first, int removed,
                                std::vector<ladder::Network> added) {
    // A network without rungs is the page's until it holds one.
    std::erase_if(added, [](const ladder::Network& n) { return n.items.empty() && !n.block; });
    if (const auto unitStep = unitStepIndex(step); unitStep && !m_pendingShown) {
        if (auto run =
                ladder::networkRunLines(m_steps[step].ladder, static_cast<std::size_t>(first),
                                        static_cast<std::size_t>(removed), added)) {
            m_document->replaceStepLines(name, m_station, *unitStep, run->first, run->removed,
                                         std::move(run->lines));
            return;
        }
    }
    ladder::StepLadder ladder = m_steps[step].ladder;
    const auto at = ladder.networks.begin() + first;
    ladder.networks.insert(ladder.networks.erase(at, at + removed),
                           std::make_move_iterator(added.begin()),
                           std::make_move_iterator(added.end()));
    commitStep(name, step, std::move(ladder));
}

void LadderPage::commitStep(const QString& name, int step, ladder::StepLadder ladder) {
    commitSteps(name, {{step, std::move(ladder)}});
}

void LadderPage::commitSteps(const QString& name,
                             std::vector<std::pair<int, ladder::StepLadder>> steps) {
    std::vector<std::pair<lang::StepAddress, ladder::StepLadder>> written;
    for (auto& [step, ladder] : steps) {
        if (m_pending && m_pending->first == step &&
            (m_pending->second >= static_cast<int>(ladder.networks.size()) ||
             !ladder.networks[m_pending->second].items.empty()))
            m_pending.reset();
        // A network without rungs is the page's until it holds one.
        std::erase_if(ladder.networks,
                      [](const ladder::Network& n) { return n.items.empty() && !n.block; });
        written.emplace_back(m_steps[step].address, std::move(ladder));
    }
    const int station = m_station;
    const blocks::LibrarySet& libraries = m_document->libraries();
    m_document->editUnitCode(name, station, [&](project::Project& p) {
        lang::UnitProgram& unit = project::programOf(p, station);
        for (const auto& [stepAddress, ladder] : written) {
            // Named, as clang 14 cannot capture a structured binding.
            const lang::StepAddress& address = stepAddress;
            if (std::none_of(unit.steps.begin(), unit.steps.end(),
                             [&](const lang::Step& s) { return s.address == address; }))
                unit.steps.insert(unit.steps.begin(), lang::Step{address, std::nullopt, {}, {}});
            ladder::setStepLadder(unit, address, ladder);
        }
        // Block instances written without statements (inserted, rebound,
        // pasted) get them, and their own private variables, in this step.
        blocks::expandInstances(p.program, libraries);
    });
}

void LadderPage::selectAdded(int step, int network, const std::vector<QString>& before) {
    NetworkItem* item = networkItem(step, network);
    if (!item)
        return;
    std::map<QString, int> counts;
    for (const QString& signature : before)
        ++counts[signature];
    for (const auto& element : item->layout().elements) {
        if (counts[signatureOf(element)]-- > 0)
            continue;
        LadderCursor cursor{step, network, std::nullopt, std::nullopt, -1};
        if (element.output >= 0) {
            cursor.output = element.path;
            cursor.outputIndex = element.output;
        } else {
            cursor.node = element.path;
        }
        setCursor(cursor);
        return;
    }
    LadderCursor cursor = m_drawing.cursor;
    cursor.step = step;
    cursor.network = network;
    if (!cursorElement() &&
        !(cursor.node && ladder::nodeAt(m_steps[step].ladder.networks[network], *cursor.node)))
        cursor = {step, network, std::nullopt, std::nullopt, -1};
    setCursor(cursor);
}

void LadderPage::insertElement(ElementKind kind) {
    if (!editable())
        return;
    if (!m_drawing.cursor.valid()) {
        if (stepCount() == 0 || networkCount(0) == 0)
            newNetwork();
        else
            setCursor({0, networkCount(0) - 1, std::nullopt, std::nullopt, -1});
    }
    const LadderCursor cursor = m_drawing.cursor;
    if (!cursor.valid())
        return;
    const ladder::Network& network = m_steps[cursor.step].ladder.networks[cursor.network];
    const bool output = ladder::isOutput(kind);
    ElementFields fields;
    fields.kind = kind;
    if (kind == ElementKind::SequenceReset)
        fields.operand = QStringLiteral("S%1.1").arg(m_station).toStdString();
    if (kind == ElementKind::Jump)
        fields.operand = "+1";
    ElementDialog dialog(m_document, m_station, output, fields, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const QString name = tr("Insert %1").arg(ElementKinds::name(kind));

    // The rung the insertion concerns: the selected one, or the network's last.
    std::optional<std::size_t> rungItem;
    if (cursor.node)
        rungItem = cursor.node->item;
    else if (cursor.output)
        rungItem = cursor.output->item;
    else
        for (std::size_t i = network.items.size(); i-- > 0;)
            if (std::holds_alternative<ladder::Rung>(network.items[i])) {
                rungItem = i;
                break;
            }

    if (output) {
        const ladder::Output made = *dialog.output();
        if (!rungItem || cursor.wholeNetwork()) {
            const std::size_t at = network.items.size();
            editNetwork(name, cursor.step, cursor.network, [&](ladder::Network& n) {
                return ladder::insertRung(n, at, ladder::Rung{std::nullopt, {made}});
            });
            return;
        }
        editNetwork(name, cursor.step, cursor.network,
                    [&](ladder::Network& n) { return ladder::addOutput(n, *rungItem, made); });
        return;
    }
    const ladder::Element made = *dialog.element();
    if (!rungItem) {
        setMessage(tr("A network starts with its output: insert a coil, latch, jump or "
                      "arithmetic box first, then its contacts."));
        return;
    }
    if (cursor.node) {
        const ladder::ElementPath at = *cursor.node;
        const Placement placement = m_placement;
        editNetwork(name, cursor.step, cursor.network, [&](ladder::Network& n) {
            switch (placement) {
            case Placement::Parallel:
                return ladder::insertInParallel(n, at, made);
            case Placement::Before:
                return ladder::insertInSeries(n, at, made, ladder::Side::Before);
            case Placement::After:
                break;
            }
            return ladder::insertInSeries(n, at, made, ladder::Side::After);
        });
        return;
    }
    // An output or the network: the element goes last in the rung's condition.
    const ladder::ElementPath root{*rungItem, {}};
    editNetwork(name, cursor.step, cursor.network, [&](ladder::Network& n) {
        return ladder::insertInSeries(n, root, made, ladder::Side::After);
    });
}

void LadderPage::editProperties() {
    if (!editable())
        return;
    const LadderCursor cursor = m_drawing.cursor;
    if (!cursor.valid())
        return;
    const ladder::Network& network = m_steps[cursor.step].ladder.networks[cursor.network];
    if (network.block) {
        editBlockPins(cursor.step, cursor.network);
        return;
    }
    if (cursor.wholeNetwork())
        return;
    if (cursor.node) {
        const ladder::Circuit* node = ladder::nodeAt(network, *cursor.node);
        if (!node || !node->isElement())
            return;
        ElementDialog dialog(m_document, m_station, false, fieldsOf(node->element), this);
        if (dialog.exec() != QDialog::Accepted)
            return;
        const ladder::Element element = *dialog.element();
        const ladder::ElementPath at = *cursor.node;
        if (element == node->element)
            return;
        editNetwork(tr("Change Element"), cursor.step, cursor.network,
                    [&](ladder::Network& n) { return ladder::replaceElement(n, at, element); });
        setCursor(cursor);
        return;
    }
    const auto& rung = std::get<ladder::Rung>(network.items[cursor.output->item]);
    const ladder::Output& old = rung.outputs[static_cast<std::size_t>(cursor.outputIndex)];
    ElementDialog dialog(m_document, m_station, true, fieldsOf(old), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    ladder::Output output = *dialog.output();
    output.location = old.location;
    if (output == old)
        return;
    const std::size_t item = cursor.output->item;
    const auto index = static_cast<std::size_t>(cursor.outputIndex);
    editNetwork(tr("Change Output"), cursor.step, cursor.network,
                [&](ladder::Network& n) { return ladder::replaceOutput(n, item, index, output); });
    setCursor(cursor);
}

void LadderPage::deleteSelection() {
    if (!editable())
        return;
    const LadderCursor cursor = m_drawing.cursor;
    if (!cursor.valid())
        return;
    if (cursor.wholeNetwork() || !m_drawing.marked.empty()) {
        deleteNetworks();
        return;
    }
    if (cursor.node) {
        const ladder::ElementPath at = *cursor.node;
        editNetwork(tr("Delete Element"), cursor.step, cursor.network,
                    [&](ladder::Network& n) { return ladder::removeNode(n, at); });
    } else {
        const std::size_t item = cursor.output->item;
        const auto index = static_cast<std::size_t>(cursor.outputIndex);
        editNetwork(tr("Delete Output"), cursor.step, cursor.network,
                    [&](ladder::Network& n) { return ladder::removeOutput(n, item, index); });
    }
    const ladder::ElementLayout* left = cursorElement();
    if (!left &&
        !(m_drawing.cursor.node && m_drawing.cursor.network < networkCount(m_drawing.cursor.step) &&
          ladder::nodeAt(m_steps[m_drawing.cursor.step].ladder.networks[m_drawing.cursor.network],
                         *m_drawing.cursor.node)))
        setCursor(cursor.network < networkCount(cursor.step)
                      ? LadderCursor{cursor.step, cursor.network, std::nullopt, std::nullopt, -1}
                      : LadderCursor{});
}

void LadderPage::newNetwork() {
    if (!editable())
        return;
    updateNetwork();
    if (stepCount() == 0) {
        setMessage(tr("This sequence has no step yet."));
        return;
    }
    const LadderCursor cursor = m_drawing.cursor;
    const int step = cursor.valid() ? cursor.step : stepCount() - 1;
    const int index = cursor.valid() ? cursor.network + 1 : networkCount(step);
    if (m_pending) {
        // Only one new network waits for its first rung; it moves here.
        m_pending.reset();
        rebuild();
    }
    m_pending = std::make_pair(step, std::min(index, networkCount(step)));
    rebuild();
    m_drawing.marked.clear();
    setCursor({m_pending->first, m_pending->second, std::nullopt, std::nullopt, -1});
    setMessage(tr("New network: insert its output first (L coil, S set, R reset, J jump ...)."));
}

void LadderPage::newConfigOption() {
    if (!editable())
        return;
    if (m_sequence != 0 || stepCount() == 0) {
        setMessage(tr("Options stand at the start of the PLC code: open the PLC Code page."));
        return;
    }
    ladder::ConfigOption option;
    ConfigOptionDialog dialog(m_document, m_station, option, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    ladder::StepLadder ladder = m_steps[0].ladder;
    // After the options already there, before the rest of the code.
    int at = 0;
    while (at < static_cast<int>(ladder.networks.size()) &&
           ladder::configOptionOf(ladder.networks[at]))
        ++at;
    ladder.networks.insert(ladder.networks.begin() + at,
                           ladder::configOptionNetwork(*dialog.option()));
    if (m_pending && m_pending->first == 0 && m_pending->second >= at)
        ++m_pending->second;
    commitStep(tr("New Config Option"), 0, std::move(ladder));
    setCursor({0, at, std::nullopt, std::nullopt, -1});
}

void LadderPage::editConfigOption(int step, int network) {
    NetworkItem* item = networkItem(step, network);
    if (!editable() || !item || !item->option())
        return;
    ConfigOptionDialog dialog(m_document, m_station, *item->option(), this);
    if (dialog.exec() != QDialog::Accepted || dialog.option() == item->option())
        return;
    const ladder::Network changed = ladder::configOptionNetwork(*dialog.option());
    editNetwork(tr("Change Config Option"), step, network, [&](ladder::Network& n) {
        n = changed;
        return ladder::EditResult{};
    });
    setCursor({step, network, std::nullopt, std::nullopt, -1});
}

void LadderPage::toggleConfigOption(int step, int network) {
    NetworkItem* item = networkItem(step, network);
    if (!editable() || !item || !item->option())
        return;
    ladder::ConfigOption option = *item->option();
    option.checked = !option.checked;
    const ladder::Network changed = ladder::configOptionNetwork(option);
    editNetwork(option.checked ? tr("Enable Option") : tr("Disable Option"), step, network,
                [&](ladder::Network& n) {
                    n = changed;
                    return ladder::EditResult{};
                });
    setCursor({step, network, std::nullopt, std::nullopt, -1});
}

void LadderPage::editNetworkComment() {
    if (!editable())
        return;
    const LadderCursor cursor = m_drawing.cursor;
    if (!cursor.valid())
        return;
    const ladder::Network& network = m_steps[cursor.step].ladder.networks[cursor.network];
    if (network.items.empty()) {
        setMessage(tr("Insert the network's output before its comment."));
        return;
    }
    NetworkCommentDialog dialog(tr("&Comment of network %1:").arg(cursor.network + 1),
                                QString::fromStdString(network.comment), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const QString comment = dialog.text();
    if (comment.toStdString() == network.comment)
        return;
    editNetwork(tr("Comment Network %1").arg(cursor.network + 1), cursor.step, cursor.network,
                [&](ladder::Network& n) {
                    n.comment = comment.trimmed().toStdString();
                    return ladder::EditResult{};
                });
    setCursor({cursor.step, cursor.network, std::nullopt, std::nullopt, -1});
}

void LadderPage::editStepComment(int step) {
    if (!editable() || step < 0 || step >= stepCount())
        return;
    const lang::StepAddress address = m_steps[step].address;
    const QString header = QString::fromStdString(lang::toString(address));
    bool ok = false;
    const QString comment =
        QInputDialog::getText(this, tr("Step Comment"), tr("Comment of step %1:").arg(header),
                              QLineEdit::Normal, m_stepComments[step], &ok)
            .trimmed();
    if (!ok || comment == m_stepComments[step])
        return;
    const int station = m_station;
    m_document->editUnitCode(tr("Comment Step %1").arg(header), station, [&](project::Project& p) {
        for (auto& s : project::programOf(p, station).steps)
            if (s.address == address)
                s.comment = comment.isEmpty()
                                ? std::nullopt
                                : std::optional<std::string>(" " + comment.toStdString());
    });
}

void LadderPage::newStep() {
    if (!editable())
        return;
    int added = -1;
    std::string refusal;
    const int station = m_station;
    const int sequence = m_sequence;
    m_document->editUnitCode(
        tr("New Step of Sequence %1").arg(sequence), station, [&](project::Project& p) {
            const project::AddedStep step = project::addStep(p, station, sequence);
            added = step.step;
            refusal = step.refusal;
        });
    if (added < 0) {
        setMessage(QString::fromStdString(refusal));
        return;
    }
    for (int s = 0; s < stepCount(); ++s)
        if (m_steps[s].address.step == added) {
            // The new step gets a first network, waiting for its output.
            m_pending = std::make_pair(s, 0);
            rebuild();
            setCursor({s, 0, std::nullopt, std::nullopt, -1});
            setMessage(tr("Step %1 added: insert the output of its first network.").arg(added));
            return;
        }
}

bool LadderPage::moveElement(const LadderCursor& from, const LadderCursor& to, ladder::Side side) {
    return transferElement(from, to, side, Transfer::Move);
}

bool LadderPage::copyElement(const LadderCursor& from, const LadderCursor& to, ladder::Side side) {
    return transferElement(from, to, side, Transfer::Copy);
}

bool LadderPage::transferElement(const LadderCursor& from, const LadderCursor& to,
                                 ladder::Side side, Transfer transfer) {
    auto exists = [this](const LadderCursor& c) {
        return c.node && c.step >= 0 && c.step < stepCount() && c.network >= 0 &&
               c.network < networkCount(c.step);
    };
    if (!editable() || !exists(from) || !exists(to))
        return false;
    updateNetwork();
    const bool sameStep = from.step == to.step;
    ladder::StepLadder source = m_steps[from.step].ladder;
    ladder::StepLadder target = sameStep ? ladder::StepLadder{} : m_steps[to.step].ladder;
    ladder::StepLadder& into = sameStep ? source : target;
    const bool move = transfer == Transfer::Move;
    const ladder::EditResult result =
        move ? ladder::moveNode(source.networks[from.network], *from.node,
                                into.networks[to.network], *to.node, side)
             : ladder::copyNode(source.networks[from.network], *from.node,
                                into.networks[to.network], *to.node, side);
    if (!result.done()) {
        const QString refusal = QString::fromStdString(result.refusal);
        setMessage(move ? tr("Not moved: %1").arg(refusal) : tr("Not copied: %1").arg(refusal));
        return false;
    }
    setMessage({});
    std::vector<std::pair<int, ladder::StepLadder>> steps;
    steps.emplace_back(from.step, std::move(source));
    if (!sameStep)
        steps.emplace_back(to.step, std::move(target));
    commitSteps(move ? tr("Move Element") : tr("Copy Element"), std::move(steps));
    setCursor(
        {to.step, std::min(to.network, networkCount(to.step) - 1), std::nullopt, std::nullopt, -1});
    return true;
}

// ----- edit mode

void LadderPage::enterEditMode() {
    if (!editable() || !m_drawing.cursor.valid())
        return;
    if (const EditSession* session = editSession()) {
        if (session->step == m_drawing.cursor.step && session->network == m_drawing.cursor.network)
            return;
        updateNetwork();
    }
    m_networkEditTool->start({m_drawing.cursor.step, m_drawing.cursor.network});
    setTool(*m_networkEditTool);
    setMessage(tr("Network %1 is in edit mode: Update (%2) keeps its edits as one step, "
                  "Undo (%3) drops them.")
                   .arg(m_drawing.cursor.network + 1)
                   .arg(LadderActions::keyOf(m_actions->updateNetwork),
                        LadderActions::keyOf(m_actions->undoNetwork)));
    repaintItems();
}

void LadderPage::updateNetwork() {
    const EditSession* current = editSession();
    if (!current)
        return;
    const EditSession session = *current;
    endEditSession();
    ladder::StepLadder ladder = m_steps[session.step].ladder;
    commitStep(tr("Edit Network %1").arg(session.network + 1), session.step, std::move(ladder));
    rebuild();
    setMessage(tr("Network %1 updated.").arg(session.network + 1));
    updateActions();
}

void LadderPage::undoNetwork() {
    const EditSession* current = editSession();
    if (!current)
        return;
    const EditSession session = *current;
    endEditSession();
    rebuild();
    setMessage(tr("The edits of network %1 were dropped.").arg(session.network + 1));
    updateActions();
}

} // namespace rs::ui
