// SPDX-License-Identifier: GPL-3.0-or-later
#include "LiveLadder.h"

#include "sim/Simulation.h"

#include <QStringList>

#include <algorithm>

namespace rs::ui {

namespace {

QString seconds(std::int64_t ms) {
    return QStringLiteral("%1 s").arg(static_cast<double>(ms) / 1000.0, 0, 'f', 2);
}

} // namespace

void LiveLadderBuilder::rebuild(LadderLiveState& state, const sim::UnitEngine& unit) {
    m_unit = &unit;
    const auto& code = unit.image().code;
    m_instructions = code.size();
    m_boxes.clear();
    for (std::size_t i = 0; i < code.size(); ++i) {
        const compiler::Instruction& in = code[i];
        const bool timer = in.op == compiler::Op::Timer;
        const bool operand = (in.op == compiler::Op::LoadA || in.op == compiler::Op::LoadB ||
                              in.op == compiler::Op::Arith) &&
                             !(in.flags & compiler::ConstantOperand) && in.operand.valid();
        if (!timer && !operand)
            continue;
        const auto key = std::make_pair(in.statement, in.element);
        if (m_boxes.empty() || m_boxes.back().key != key)
            m_boxes.push_back({key, {}, {}});
        m_boxes.back().instructions.push_back(i);
    }
    state.annotations.clear();
    for (Box& box : m_boxes) {
        box.values.clear();
        readValues(unit, box);
        state.annotations[box.key] = textOf(unit, box);
    }
}

void LiveLadderBuilder::reset() {
    m_unit = nullptr;
    m_power.reset();
}

bool LiveLadderBuilder::readValues(const sim::UnitEngine& unit, Box& box) const {
    const auto& code = unit.image().code;
    bool changed = false;
    std::size_t at = 0;
    const auto put = [&](std::int64_t value) {
        if (at == box.values.size()) {
            box.values.push_back(value);
            changed = true;
        } else if (box.values[at] != value) {
            box.values[at] = value;
            changed = true;
        }
        ++at;
    };
    for (std::size_t index : box.instructions) {
        const compiler::Instruction& in = code[index];
        if (in.op == compiler::Op::Timer) {
            const std::int64_t preset =
                10 * ((in.flags & compiler::ConstantOperand) ? in.constant : unit.read(in.operand));
            put(std::min(unit.timer(in.slot).elapsedMs, preset));
            put(preset);
        } else {
            put(unit.read(in.operand));
        }
    }
    return changed;
}

QString LiveLadderBuilder::textOf(const sim::UnitEngine& unit, const Box& box) const {
    const auto& code = unit.image().code;
    const compiler::Instruction& first = code[box.instructions.front()];
    if (first.op == compiler::Op::Timer)
        return seconds(box.values[0]) + QStringLiteral(" / ") + seconds(box.values[1]);
    QStringList parts;
    for (std::size_t i = 0; i < box.instructions.size(); ++i) {
        const QString part =
            QStringLiteral("%1=%2")
                .arg(QString::fromStdString(lang::toString(code[box.instructions[i]].operand)))
                .arg(box.values[i]);
        if (!parts.contains(part))
            parts << part;
    }
    return parts.join(QStringLiteral("  "));
}

void LiveLadderBuilder::update(LadderLiveState& state, const sim::Simulation& simulation,
                               int station, const std::set<lang::Address>& watched) {
    const sim::UnitEngine* unit = simulation.unit(station);
    if (!unit) {
        state = LadderLiveState{};
        reset();
        return;
    }
    m_power.update(state.power, *unit);
    state.power.values.clear();
    for (const lang::Address& address : watched)
        state.power.values.emplace(address, unit->read(address));
    if (unit != m_unit || m_instructions != unit->image().code.size()) {
        rebuild(state, *unit);
    } else {
        for (Box& box : m_boxes)
            if (readValues(*unit, box))
                state.annotations[box.key] = textOf(*unit, box);
    }
    state.forcedElements.clear();
    const auto& code = unit->image().code;
    for (const Box& box : m_boxes)
        for (std::size_t index : box.instructions)
            if (unit->forces().count(code[index].operand))
                state.forcedElements.insert(box.key);
    state.forced.clear();
    for (const auto& [address, value] : unit->forces()) {
        const QString text = QString::fromStdString(lang::toString(address));
        state.forced.insert(text);
        state.forced.insert(QLatin1Char('/') + text);
    }
    state.activeSteps.clear();
    for (int sequence = 1; sequence <= 9; ++sequence)
        if (unit->hasSequence(sequence))
            state.activeSteps[sequence] = unit->activeStep(sequence);
}

} // namespace rs::ui
