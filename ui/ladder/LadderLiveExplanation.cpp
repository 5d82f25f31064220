// SPDX-License-Identifier: GPL-3.0-or-later
// While live: why the selected output is on or off, from what its rung
// conducted in the last scan (ladder::powerPaths), said in the page's status
// line and marked on the rung.
#include "LadderPage.h"

#include "NetworkItem.h"
#include "document/ProjectDocument.h"
#include "ladder/ElementVocabulary.h"
#include "ladder/PowerPaths.h"

#include <QStringList>

namespace rs::ui {

namespace {

using ladder::ElementKind;

bool isTimer(ElementKind kind) {
    return kind == ElementKind::OnDelayTimer || kind == ElementKind::PulseTimer ||
           kind == ElementKind::OffDelayTimer;
}

bool isBitOutput(ElementKind kind) {
    return kind == ElementKind::Coil || kind == ElementKind::Set || kind == ElementKind::Reset ||
           kind == ElementKind::Toggle;
}

// How the message names an element: its operand's name (else its address),
// an edge as written, a comparison with its value, a timer with its preset.
QString labelOf(const ladder::ElementLayout& e) {
    const QString operand = e.name.isEmpty() ? e.address : e.name;
    if (e.kind == ElementKind::NormallyClosed)
        return QLatin1Char('/') + operand;
    if (e.kind == ElementKind::Comparison)
        return (operand + QLatin1Char(' ') + e.text).trimmed();
    if (isTimer(e.kind))
        return (e.text + QLatin1Char(' ') + e.address).trimmed();
    if (ladder::isEdge(e.kind)) {
        const auto mark = ladder::infoOf(e.kind).mark;
        return QString::fromUtf8(mark.data(), qsizetype(mark.size())) + QLatin1Char('(') + operand +
               QLatin1Char(')');
    }
    return operand;
}

} // namespace

void LadderPage::explainOutput() {
    const QString before = m_explanation;
    m_drawing.blocking.clear();
    m_drawing.holding.clear();
    m_explanation.clear();
    const LadderCursor& cursor = m_drawing.cursor;
    NetworkItem* item = networkItem(cursor.step, cursor.network);
    const ladder::ElementLayout* output = cursorElement();
    if (!m_drawing.live || !item || !output || output->output < 0 || !cursor.output ||
        cursor.output->item >= item->network().items.size()) {
        if (!before.isEmpty())
            setMessage({});
        return;
    }
    const auto* rung = std::get_if<ladder::Rung>(&item->network().items[cursor.output->item]);
    if (!rung) {
        setMessage({});
        return;
    }
    const render::PowerSnapshot& power = m_drawing.live->power;
    // The condition's elements carry the rung's first statement (its first output's).
    const std::uint32_t statement = output->statement;
    const std::uint32_t condition = statement - static_cast<std::uint32_t>(output->output);
    const QString name = labelOf(*output);
    if (!power.ran(statement)) {
        m_explanation = tr("%1 did not run: its step is not active").arg(name);
        setMessage(m_explanation);
        return;
    }
    const ladder::PowerPaths paths = ladder::powerPaths(
        rung->condition, [&](std::uint16_t element) { return power.conducts(condition, element); });
    const auto elementOf = [&](std::uint16_t number) -> const ladder::ElementLayout* {
        for (const auto& e : item->layout().elements)
            if (e.statement == condition && e.element == number && e.output < 0)
                return &e;
        return nullptr;
    };
    QStringList blockers;
    for (std::uint16_t number : paths.blockers) {
        const ladder::ElementLayout* e = elementOf(number);
        if (!e)
            continue;
        const QString label = labelOf(*e);
        if (e->kind == ElementKind::Comparison)
            blockers << (e->negated ? tr("%1 is true") : tr("%1 is false")).arg(label);
        else if (isTimer(e->kind))
            blockers << (e->negated ? tr("%1 is on") : tr("%1 is off")).arg(label);
        else
            blockers << tr("%1 is open").arg(label);
    }
    QStringList holding;
    for (std::uint16_t number : paths.holding)
        if (const ladder::ElementLayout* e = elementOf(number))
            holding << labelOf(*e);
    if (paths.conducting)
        for (std::uint16_t number : paths.holding)
            m_drawing.holding.insert({condition, number});
    else
        for (std::uint16_t number : paths.blockers)
            m_drawing.blocking.insert({condition, number});

    const bool energised = power.conducts(statement, 0);
    // A bit output says its variable's value (forced, or set or reset
    // elsewhere); any other output is on when its rung drives it.
    const bool bit = isBitOutput(output->kind);
    const bool on = bit ? power.closed(statement, 0) : energised;
    const bool forced = bit && m_drawing.live->forced.count(output->address) > 0;
    const QString path = holding.join(QStringLiteral(", "));
    if (on && energised)
        m_explanation = holding.isEmpty() ? tr("%1 is on").arg(name)
                                          : tr("%1 is on through %2").arg(name, path);
    else if (!on && !energised)
        m_explanation = tr("%1 is off: %2").arg(name, blockers.join(QStringLiteral(", ")));
    else if (on)
        m_explanation = (forced ? tr("%1 is forced on; its rung is off: %2")
                                : tr("%1 is on; its rung is off: %2"))
                            .arg(name, blockers.join(QStringLiteral(", ")));
    else if (holding.isEmpty())
        m_explanation = forced ? tr("%1 is forced off; its rung is on").arg(name)
                               : tr("%1 is off; its rung is on").arg(name);
    else
        m_explanation = (forced ? tr("%1 is forced off; its rung is on through %2")
                                : tr("%1 is off; its rung is on through %2"))
                            .arg(name, path);
    setMessage(m_explanation);
}

} // namespace rs::ui
