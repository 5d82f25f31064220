// SPDX-License-Identifier: GPL-3.0-or-later
#include "VcdWriter.h"

namespace rs::sim {

namespace {

std::string identifier(std::size_t index) {
    std::string id;
    do {
        id += static_cast<char>('!' + index % 94);
        index /= 94;
    } while (index);
    return id;
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

VcdWriter::VcdWriter(std::vector<VcdSignal> traced) : m_signals(std::move(traced)) {
    for (std::size_t i = 0; i < m_signals.size(); ++i)
        m_ids.push_back(identifier(i));
    m_last.assign(m_signals.size(), 0);
}

void VcdWriter::sample(std::int64_t timeMs, const std::vector<std::int64_t>& values) {
    std::string changes;
    for (std::size_t i = 0; i < m_signals.size(); ++i) {
        const std::int64_t value = values[i];
        if (m_sampled && value == m_last[i])
            continue;
        m_last[i] = value;
        if (m_signals[i].bit)
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

std::string VcdWriter::text(const std::string& title) const {
    std::string out = "$comment " + title +
                      " $end\n$version Rungsmith " RUNGSMITH_VERSION " $end\n"
                      "$timescale 1ms $end\n";
    const std::string* scope = nullptr;
    for (std::size_t i = 0; i < m_signals.size(); ++i) {
        const VcdSignal& signal = m_signals[i];
        if (!scope || signal.scope != *scope) {
            if (scope)
                out += "$upscope $end\n";
            scope = &signal.scope;
            out += "$scope module " + signal.scope + " $end\n";
        }
        out += signal.bit ? "$var wire 1 " : "$var integer 32 ";
        out += m_ids[i] + " " + signal.reference + " $end\n";
    }
    if (scope)
        out += "$upscope $end\n";
    out += "$enddefinitions $end\n";
    return out + m_changes;
}

} // namespace rs::sim
