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
    m_boxesOf.clear();
    auto& memory = const_cast<sim::UnitMemory&>(unit.memory());
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
            m_boxes.push_back({key, {}, {}, {}, {}});
        m_boxes.back().instructions.push_back(i);
        Source source;
        if (timer) {
            source.kind = Source::Kind::Timer;
            source.slot = in.slot;
            if (in.flags & compiler::ConstantOperand)
                source.preset = 10 * std::int64_t{in.constant};
            else
                source.word = sim::wordRef(memory, in.operand);
        } else if (in.operand.kind == lang::AddressKind::Sequence) {
            source.kind = Source::Kind::Step;
            source.sequence = in.operand.index;
        } else {
            // As UnitEngine::read: a number where the address names one, else a bit.
            source.word = sim::wordRef(memory, in.operand);
            if (source.word.kind == sim::WordRef::Kind::None) {
                source.kind = Source::Kind::Bit;
                source.bit = sim::bitRef(memory, in.operand, false);
            }
        }
        Box& box = m_boxes.back();
        if (!timer) {
            // One label for each operand: the same operand twice reads the same value.
            const QString label =
                QString::fromStdString(lang::toString(in.operand)) + QLatin1Char('=');
            if (std::none_of(box.labels.begin(), box.labels.end(),
                             [&](const auto& known) { return known.second == label; }))
                box.labels.emplace_back(box.sources.size(), label);
        }
        box.sources.push_back(source);
        if (in.operand.valid())
            m_boxesOf[in.operand].push_back(key);
    }
    state.annotations.clear();
    for (Box& box : m_boxes) {
        box.values.clear();
        readValues(unit, box);
        state.annotations[box.key] = textOf(box);
    }
}

void LiveLadderBuilder::reset() {
    m_unit = nullptr;
    m_power.reset();
}

bool LiveLadderBuilder::readValues(const sim::UnitEngine& unit, Box& box) const {
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
    for (const Source& source : box.sources) {
        switch (source.kind) {
        case Source::Kind::Timer: {
            const std::int64_t preset = source.word.kind == sim::WordRef::Kind::None
                                            ? source.preset
                                            : 10 * source.word.read();
            put(std::min(unit.timer(source.slot).elapsedMs, preset));
            put(preset);
            break;
        }
        case Source::Kind::Word:
            put(source.word.read());
            break;
        case Source::Kind::Bit:
            put(source.bit.read());
            break;
        case Source::Kind::Step:
            put(unit.activeStep(source.sequence));
            break;
        }
    }
    return changed;
}

QString LiveLadderBuilder::textOf(const Box& box) {
    if (box.sources.front().kind == Source::Kind::Timer)
        return seconds(box.values[0]) + QStringLiteral(" / ") + seconds(box.values[1]);
    QString text;
    for (const auto& [index, label] : box.labels) {
        if (!text.isEmpty())
            text += QStringLiteral("  ");
        text += label + QString::number(box.values[index]);
    }
    return text;
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
                state.annotations[box.key] = textOf(box);
    }
    state.forcedElements.clear();
    for (const auto& [address, value] : unit->forces())
        if (auto boxes = m_boxesOf.find(address); boxes != m_boxesOf.end())
            state.forcedElements.insert(boxes->second.begin(), boxes->second.end());
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
