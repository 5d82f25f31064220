// SPDX-License-Identifier: GPL-3.0-or-later
#include "VcdTrace.h"

#include <algorithm>
#include <set>

namespace rs::sim {

namespace {

bool isBitSignal(const lang::Address& a) {
    return a.isBit() && a.kind != lang::AddressKind::AnalogInput;
}

// The name inside its unit's scope: Q0.2 of unit 0 is "Q2", DR0.4.Lo is "DR4_Lo".
std::string reference(const lang::Address& a) {
    if (a.kind == lang::AddressKind::Sequence)
        return "S" + std::to_string(a.index) + "_step";
    std::string text = lang::toString(a);
    const std::string unit = std::to_string(a.unit) + ".";
    const std::string prefix(lang::addressPrefix(a.kind));
    text.erase(prefix.size(), unit.size());
    std::replace(text.begin(), text.end(), '.', '_');
    return text;
}

std::vector<VcdSignal> signalsOf(const std::vector<lang::Address>& variables) {
    std::vector<VcdSignal> traced;
    for (const auto& a : variables)
        traced.push_back({"pluto" + std::to_string(a.unit), reference(a), isBitSignal(a)});
    return traced;
}

} // namespace

VcdTrace::VcdTrace(std::vector<lang::Address> variables)
    : m_signals(std::move(variables)), m_writer(signalsOf(m_signals)) {}

void VcdTrace::sample(const Simulation& simulation) {
    std::vector<std::int64_t> values;
    values.reserve(m_signals.size());
    for (const auto& signal : m_signals)
        values.push_back(simulation.value(signal));
    sample(simulation.timeMs(), values);
}

void VcdTrace::sample(std::int64_t timeMs, const std::vector<std::int64_t>& values) {
    m_writer.sample(timeMs, values);
}

std::string VcdTrace::text(const std::string& title) const {
    return m_writer.text(title);
}

std::vector<lang::Address> traceSignals(const std::vector<compiler::UnitImage>& images,
                                        const std::vector<lang::Address>& touched) {
    std::set<lang::Address> variables(touched.begin(), touched.end());
    for (const auto& image : images)
        for (const auto& in : image.code)
            switch (in.op) {
            case compiler::Op::Coil:
            case compiler::Op::Set:
            case compiler::Op::Reset:
            case compiler::Op::Toggle:
            case compiler::Op::Arith:
                variables.insert(in.operand);
                break;
            case compiler::Op::Argument:
                if (in.aux & compiler::ArgumentWritten)
                    variables.insert(in.operand);
                break;
            default:
                break;
            }
    return {variables.begin(), variables.end()};
}

} // namespace rs::sim
