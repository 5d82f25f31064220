// SPDX-License-Identifier: GPL-3.0-or-later
#include "VcdTrace.h"

#include <algorithm>
#include <set>

namespace rs::sim {

namespace {

bool isBitSignal(const lang::Address& a) {
    return a.isBit() && a.kind != lang::AddressKind::AnalogInput;
}

std::string identifier(std::size_t index) {
    std::string id;
    do {
        id += static_cast<char>('!' + index % 94);
        index /= 94;
    } while (index);
    return id;
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

std::string binary(std::int64_t value) {
    auto bits = static_cast<std::uint32_t>(static_cast<std::int32_t>(value));
    std::string text;
    do {
        text.insert(text.begin(), (bits & 1u) ? '1' : '0');
        bits >>= 1;
    } while (bits);
    return text;
}

} // namespace

VcdTrace::VcdTrace(std::vector<lang::Address> variables) : m_signals(std::move(variables)) {
    for (std::size_t i = 0; i < m_signals.size(); ++i)
        m_ids.push_back(identifier(i));
    m_last.assign(m_signals.size(), 0);
}

void VcdTrace::sample(const Simulation& simulation) {
    std::vector<std::int64_t> values;
    values.reserve(m_signals.size());
    for (const auto& signal : m_signals)
        values.push_back(simulation.value(signal));
    sample(simulation.timeMs(), values);
}

void VcdTrace::sample(std::int64_t timeMs, const std::vector<std::int64_t>& values) {
    std::string changes;
    for (std::size_t i = 0; i < m_signals.size(); ++i) {
        const std::int64_t value = values[i];
        if (m_sampled && value == m_last[i])
            continue;
        m_last[i] = value;
        if (isBitSignal(m_signals[i]))
            changes += (value ? "1" : "0") + m_ids[i] + "\n";
        else
            changes += "b" + binary(value) + " " + m_ids[i] + "\n";
    }
    if (!m_sampled) {
        m_changes += "#" + std::to_string(timeMs) + "\n$dumpvars\n" + changes + "$end\n";
        m_sampled = true;
    } else if (!changes.empty()) {
        m_changes += "#" + std::to_string(timeMs) + "\n" + changes;
    }
}

std::string VcdTrace::text(const std::string& title) const {
    std::string out = "$comment " + title +
                      " $end\n$version Rungsmith " RUNGSMITH_VERSION " $end\n"
                      "$timescale 1ms $end\n";
    int unit = -1;
    for (std::size_t i = 0; i < m_signals.size(); ++i) {
        const auto& a = m_signals[i];
        if (a.unit != unit) {
            if (unit >= 0)
                out += "$upscope $end\n";
            unit = a.unit;
            out += "$scope module pluto" + std::to_string(unit) + " $end\n";
        }
        out += isBitSignal(a) ? "$var wire 1 " : "$var integer 32 ";
        out += m_ids[i] + " " + reference(a) + " $end\n";
    }
    if (unit >= 0)
        out += "$upscope $end\n";
    out += "$enddefinitions $end\n";
    return out + m_changes;
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
