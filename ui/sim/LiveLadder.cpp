#include "LiveLadder.h"

#include "sim/Simulation.h"

namespace rs::ui {

namespace {

QString seconds(std::int64_t ms) {
    return QStringLiteral("%1 s").arg(static_cast<double>(ms) / 1000.0, 0, 'f', 2);
}

QString valueOf(const sim::UnitEngine& unit, const lang::Address& address) {
    return QStringLiteral("%1 = %2")
        .arg(QString::fromStdString(lang::toString(address)))
        .arg(unit.read(address));
}

} // namespace

render::PowerSnapshot powerSnapshot(const sim::UnitEngine& unit) {
    render::PowerSnapshot snapshot;
    const auto& code = unit.image().code;
    const auto& conduction = unit.conduction();
    render::StatementPower* current = nullptr;
    std::uint32_t currentStatement = 0;
    for (std::size_t i = 0; i < code.size(); ++i) {
        if (conduction[i] == sim::Conduction::NotRun)
            continue;
        const compiler::Instruction& in = code[i];
        if (!current || currentStatement != in.statement) {
            current = &snapshot.statements[in.statement];
            currentStatement = in.statement;
        }
        const bool on = conduction[i] == sim::Conduction::On;
        if (in.element == 0) {
            // The rung's start and its output both carry element 0; the output comes last.
            current->energised = on;
        } else if (on) {
            current->conducting.insert(in.element);
        } else {
            current->conducting.erase(in.element);
        }
    }
    return snapshot;
}

std::map<std::pair<std::uint32_t, std::uint16_t>, QString>
boxAnnotations(const sim::UnitEngine& unit) {
    std::map<std::pair<std::uint32_t, std::uint16_t>, QString> annotations;
    for (const compiler::Instruction& in : unit.image().code) {
        const auto key = std::make_pair(in.statement, in.element);
        switch (in.op) {
        case compiler::Op::Timer: {
            const std::int64_t preset =
                10 * ((in.flags & compiler::ConstantOperand) ? in.constant : unit.read(in.operand));
            const std::int64_t elapsed = std::min(unit.timer(in.slot).elapsedMs, preset);
            annotations[key] = seconds(elapsed) + QStringLiteral(" / ") + seconds(preset);
            break;
        }
        case compiler::Op::LoadA:
        case compiler::Op::LoadB:
        case compiler::Op::Arith:
            if (!(in.flags & compiler::ConstantOperand) && in.operand.valid()) {
                QString& text = annotations[key];
                const QString value = valueOf(unit, in.operand);
                if (!text.contains(value))
                    text += (text.isEmpty() ? QString() : QStringLiteral(", ")) + value;
            }
            break;
        default:
            break;
        }
    }
    return annotations;
}

void fillLiveState(LadderLiveState& state, const sim::Simulation& simulation, int station) {
    state = LadderLiveState{};
    const sim::UnitEngine* unit = simulation.unit(station);
    if (!unit)
        return;
    state.power = powerSnapshot(*unit);
    state.annotations = boxAnnotations(*unit);
    for (const auto& [address, value] : unit->forces()) {
        const QString text = QString::fromStdString(lang::toString(address));
        state.forced.insert(text);
        state.forced.insert(QLatin1Char('/') + text);
    }
    for (int sequence = 1; sequence <= 9; ++sequence)
        if (unit->hasSequence(sequence))
            state.activeSteps[sequence] = unit->activeStep(sequence);
}

} // namespace rs::ui
