#include "LiveLadder.h"

#include "sim/Simulation.h"

#include <QStringList>

#include <algorithm>
#include <cstring>

namespace rs::ui {

namespace {

QString seconds(std::int64_t ms) {
    return QStringLiteral("%1 s").arg(static_cast<double>(ms) / 1000.0, 0, 'f', 2);
}

// Adds what the instructions [first, first + count) of one statement did to
// its power; false when none of them ran.
bool statementPower(const sim::UnitEngine& unit, std::size_t first, std::size_t count,
                    render::StatementPower& power) {
    const auto& code = unit.image().code;
    const auto& conduction = unit.conduction();
    bool ran = false;
    for (std::size_t i = first; i < first + count; ++i) {
        if (conduction[i] == sim::Conduction::NotRun)
            continue;
        ran = true;
        const bool on = conduction[i] == sim::Conduction::On;
        const std::uint16_t element = code[i].element;
        if (element == 0)
            power.energised = on; // the rung's start and its output; the output comes last
        else if (on)
            power.conducting.insert(element);
        else
            power.conducting.erase(element);
    }
    return ran;
}

} // namespace

render::PowerSnapshot powerSnapshot(const sim::UnitEngine& unit) {
    render::PowerSnapshot snapshot;
    const auto& code = unit.image().code;
    for (std::size_t first = 0; first < code.size();) {
        std::size_t end = first + 1;
        while (end < code.size() && code[end].statement == code[first].statement)
            ++end;
        auto [power, added] = snapshot.statements.try_emplace(code[first].statement);
        if (!statementPower(unit, first, end - first, power->second) && added)
            snapshot.statements.erase(power);
        first = end;
    }
    return snapshot;
}

void LiveLadderBuilder::rebuild(LadderLiveState& state, const sim::UnitEngine& unit) {
    m_unit = &unit;
    const auto& code = unit.image().code;
    m_statements.clear();
    m_boxes.clear();
    for (std::size_t i = 0; i < code.size(); ++i) {
        const compiler::Instruction& in = code[i];
        if (m_statements.empty() || m_statements.back().number != in.statement ||
            m_statements.back().first + m_statements.back().count != i)
            m_statements.push_back({in.statement, i, 0});
        ++m_statements.back().count;
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
    state.power = powerSnapshot(unit);
    state.annotations.clear();
    for (Box& box : m_boxes) {
        box.values.clear();
        readValues(unit, box);
        state.annotations[box.key] = textOf(unit, box);
    }
    const auto& conduction = unit.conduction();
    m_conduction.resize(conduction.size());
    std::memcpy(m_conduction.data(), conduction.data(), conduction.size());
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
                               int station) {
    const sim::UnitEngine* unit = simulation.unit(station);
    if (!unit) {
        state = LadderLiveState{};
        m_unit = nullptr;
        return;
    }
    if (unit != m_unit || m_conduction.size() != unit->conduction().size()) {
        rebuild(state, *unit);
    } else {
        const auto* now = reinterpret_cast<const std::uint8_t*>(unit->conduction().data());
        std::uint8_t* before = m_conduction.data();
        const std::size_t size = m_conduction.size();
        // Only where the marks differ: usually a few statements of thousands.
        std::size_t at = 0;
        while (at < size) {
            const std::size_t differs = static_cast<std::size_t>(
                std::mismatch(before + at, before + size, now + at).first - before);
            if (differs == size)
                break;
            const auto statement = std::prev(std::upper_bound(
                m_statements.begin(), m_statements.end(), differs,
                [](std::size_t index, const Statement& s) { return index < s.first; }));
            std::memcpy(before + statement->first, now + statement->first, statement->count);
            render::StatementPower power;
            if (statementPower(*unit, statement->first, statement->count, power))
                state.power.statements[statement->number] = std::move(power);
            else
                state.power.statements.erase(statement->number);
            at = statement->first + statement->count;
        }
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
