// SPDX-License-Identifier: GPL-3.0-or-later
#include "Scenario.h"

#include "ScenarioReader.h"

#include "lang/SymbolicName.h"
#include "lang/TextCase.h"
#include "project/UnitAsiOptions.h"
#include "project/Utf8Text.h"

#include <algorithm>
#include <charconv>
#include <limits>

namespace rs::sim {

namespace {

bool isBitOperand(const lang::Address& a) {
    return a.isBit() && a.kind != lang::AddressKind::AnalogInput;
}

} // namespace

namespace scenario_text {

// Columns count characters, not bytes.
int columnAt(std::string_view line, std::size_t offset) {
    int column = 1;
    for (std::size_t i = 0; i < offset && i < line.size(); ++i)
        if (!project::isUtf8Continuation(line[i]))
            ++column;
    return column;
}

std::vector<Word> splitWords(std::string_view line) {
    std::vector<Word> words;
    std::size_t pos = 0;
    int column = 1;
    auto advance = [&] {
        if (!project::isUtf8Continuation(line[pos]))
            ++column;
        ++pos;
    };
    while (pos < line.size()) {
        while (pos < line.size() && (line[pos] == ' ' || line[pos] == '\t'))
            advance();
        const std::size_t start = pos;
        const int startColumn = column;
        while (pos < line.size() && line[pos] != ' ' && line[pos] != '\t')
            advance();
        if (pos > start)
            words.push_back({line.substr(start, pos - start), startColumn});
    }
    return words;
}

Number parseInteger(std::string_view text, std::int64_t& value) {
    if (!text.empty() && text.front() == '+')
        text.remove_prefix(1);
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || end != text.data() + text.size() ||
        (error != std::errc() && error != std::errc::result_out_of_range))
        return Number::Malformed;
    return error == std::errc() ? Number::Ok : Number::OutOfRange;
}

std::string rangeText(const ValueRange& range) {
    if (range.low == 0 && range.high == 1)
        return "0 or 1";
    return std::to_string(range.low) + ".." + std::to_string(range.high);
}

} // namespace scenario_text

ValueRange valueRange(const lang::Address& a) {
    if (isBitOperand(a))
        return {0, 1, "a bit"};
    switch (a.kind) {
    case lang::AddressKind::Register:
    case lang::AddressKind::DoubleRegisterLow:
    case lang::AddressKind::DoubleRegisterHigh:
        return {-32768, 32767, "a register"};
    case lang::AddressKind::Sequence:
        return {0, 254, "a sequence's step number"};
    default:
        return {std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max(),
                "a 32-bit value"};
    }
}

bool parseDuration(std::string_view text, std::int64_t& ms) {
    const std::string lower = lang::toLower(text);
    std::string_view t(lower);
    auto number = [](std::string_view digits, std::int64_t scale, std::int64_t& out) {
        // Decimal with an optional fraction, in units of `scale` ms; the result must be whole ms.
        const std::size_t dot = digits.find('.');
        std::string_view whole = digits.substr(0, dot);
        std::string_view fraction =
            dot == std::string_view::npos ? std::string_view() : digits.substr(dot + 1);
        if (whole.empty() || whole.find_first_not_of("0123456789") != std::string_view::npos ||
            fraction.find_first_not_of("0123456789") != std::string_view::npos ||
            whole.size() > 9 || fraction.size() > 6 ||
            (dot != std::string_view::npos && fraction.empty()))
            return false;
        std::int64_t value = 0;
        std::from_chars(whole.data(), whole.data() + whole.size(), value);
        std::int64_t micro = value * scale * 1000;
        std::int64_t place = scale * 1000;
        for (char c : fraction) {
            place /= 10;
            micro += (c - '0') * place;
            if (place == 0 && c != '0')
                return false;
        }
        if (micro % 1000 != 0)
            return false;
        out = micro / 1000;
        return true;
    };
    if (t.ends_with("ms"))
        return number(t.substr(0, t.size() - 2), 1, ms);
    if (t.ends_with("min"))
        return number(t.substr(0, t.size() - 3), 60000, ms);
    if (t.ends_with("s"))
        return number(t.substr(0, t.size() - 1), 1000, ms);
    // The language's notation: 2s50 is 2.50 s.
    const std::size_t s = t.find('s');
    if (s == std::string_view::npos || s == 0)
        return false;
    std::string_view whole = t.substr(0, s);
    std::string_view hundredths = t.substr(s + 1);
    if (hundredths.empty() || hundredths.size() > 2 ||
        whole.find_first_not_of("0123456789") != std::string_view::npos ||
        hundredths.find_first_not_of("0123456789") != std::string_view::npos || whole.size() > 9)
        return false;
    std::int64_t seconds = 0;
    std::int64_t fraction = 0;
    std::from_chars(whole.data(), whole.data() + whole.size(), seconds);
    std::from_chars(hundredths.data(), hundredths.data() + hundredths.size(), fraction);
    if (hundredths.size() == 1)
        fraction *= 10;
    ms = seconds * 1000 + fraction * 10;
    return true;
}

OperandNames::OperandNames(const project::Project& project) {
    m_stations = project.stations();
    auto add = [&](const std::vector<lang::Line>& lines) {
        for (const auto& line : lines)
            if (const auto* declaration = std::get_if<lang::Declaration>(&line.body))
                if (const auto* name = std::get_if<lang::NameDeclaration>(&declaration->body)) {
                    const std::string key = lang::foldName(name->name);
                    auto it = std::find_if(m_names.begin(), m_names.end(),
                                           [&](const auto& entry) { return entry.first == key; });
                    if (it == m_names.end())
                        m_names.push_back({key, {name->variable.address, false, name->name}});
                    else if (!(it->second.address == name->variable.address))
                        it->second.ambiguous = true;
                }
    };
    add(project.program.preamble);
    for (const auto& unit : project.program.units) {
        add(unit.declarations);
        for (const auto& step : unit.steps)
            m_sequences.emplace_back(step.address.unit, step.address.sequence);
    }
    std::sort(m_sequences.begin(), m_sequences.end());
    for (const auto& [station, options] : project.asiOptions)
        for (const auto& [slave, setup] : options.slaves)
            if (project::hasChannels(setup.type) && !slave.b)
                m_channelSlaves.push_back({lang::AddressKind::AsiInput, station, slave.number});
}

bool OperandNames::resolveChannel(std::string_view word, lang::Address& address, int& channel,
                                  std::string& error) const {
    channel = 0;
    const std::string folded = lang::toLower(word);
    if (word.size() > 4 && (folded.ends_with(".ch1") || folded.ends_with(".ch2"))) {
        channel = folded.back() - '0';
        word.remove_suffix(4);
    }
    if (!resolve(word, address, error))
        return false;
    if (channel && std::find(m_channelSlaves.begin(), m_channelSlaves.end(), address) ==
                       m_channelSlaves.end()) {
        error = lang::toString(address) +
                " is no safe input slave of the AS-i Options page; only those have the "
                "channels ch1 and ch2";
        return false;
    }
    return true;
}

std::string OperandNames::nameOf(const lang::Address& address) const {
    for (const auto& [key, entry] : m_names)
        if (entry.address == address && !entry.ambiguous)
            return entry.spelling;
    return {};
}

bool OperandNames::hasSequence(int station, int sequence) const {
    return std::binary_search(m_sequences.begin(), m_sequences.end(), std::pair(station, sequence));
}

bool OperandNames::hasStation(int station) const {
    return std::find(m_stations.begin(), m_stations.end(), station) != m_stations.end();
}

bool OperandNames::resolve(std::string_view word, lang::Address& address,
                           std::string& error) const {
    lang::AddressWord read = lang::readAddressWord(word);
    if (read.shape == lang::AddressWord::Shape::Variable) {
        address = read.address;
        return true;
    }
    if (read.shape == lang::AddressWord::Shape::Malformed) {
        error = read.error;
        return false;
    }
    if (read.shape == lang::AddressWord::Shape::Step) {
        error = "'" + std::string(word) +
                "' is a step header; write S<unit>.<sequence> for the "
                "active step of a sequence";
        return false;
    }
    const std::string key = lang::foldName(word);
    for (const auto& [name, entry] : m_names)
        if (name == key) {
            if (entry.ambiguous) {
                error =
                    "'" + std::string(word) + "' names variables of several units; use the address";
                return false;
            }
            address = entry.address;
            return true;
        }
    if (lang::systemName(word, 0).valid()) {
        if (m_stations.size() != 1) {
            error = "'" + std::string(word) + "' is in every unit; use the address (SM<unit>.<n>)";
            return false;
        }
        address = lang::systemName(word, m_stations.front());
        return true;
    }
    error = "unknown operand '" + std::string(word) + "': use an address or a declared name";
    return false;
}

Scenario parseScenario(std::string_view text, const OperandNames& names) {
    return readScenario(text, names);
}

} // namespace rs::sim
