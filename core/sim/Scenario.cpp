// SPDX-License-Identifier: GPL-3.0-or-later
#include "Scenario.h"

#include "lang/SymbolicName.h"
#include "lang/TextCase.h"
#include "project/UnitAsiOptions.h"
#include "project/Utf8Text.h"

#include <algorithm>
#include <charconv>
#include <limits>

namespace rs::sim {

namespace {

struct Word {
    std::string_view text;
    int column;
};

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

enum class Number { Ok, Malformed, OutOfRange };

Number parseInteger(std::string_view text, std::int64_t& value) {
    if (!text.empty() && text.front() == '+')
        text.remove_prefix(1);
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || end != text.data() + text.size() ||
        (error != std::errc() && error != std::errc::result_out_of_range))
        return Number::Malformed;
    return error == std::errc() ? Number::Ok : Number::OutOfRange;
}

bool isBitOperand(const lang::Address& a) {
    return a.isBit() && a.kind != lang::AddressKind::AnalogInput;
}

std::string rangeText(const ValueRange& range) {
    if (range.low == 0 && range.high == 1)
        return "0 or 1";
    return std::to_string(range.low) + ".." + std::to_string(range.high);
}

} // namespace

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
    Scenario scenario;
    if (text.starts_with("\xEF\xBB\xBF"))
        text.remove_prefix(3);
    int lineNumber = 0;
    bool timeStarted = false;
    bool expects = false;
    std::int64_t cycleMs = 10; // the simulation's own until a `cycle` line
    std::int64_t virtualMs = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        // A line ends at LF, CRLF or a lone CR.
        std::size_t end = text.find_first_of("\r\n", pos);
        if (end == std::string_view::npos)
            end = text.size();
        std::string_view line = text.substr(pos, end - pos);
        pos = end + (text.substr(end, 2) == "\r\n" ? 2 : 1);
        ++lineNumber;
        if (const std::size_t comment = line.find_first_of(";#"); comment != std::string_view::npos)
            line = line.substr(0, comment);
        if (const auto fault = project::findTextFault(line)) {
            scenario.diagnostics.push_back(
                {lang::Severity::Error, lineNumber, columnAt(line, fault->offset), fault->message});
            continue;
        }
        std::vector<Word> words = splitWords(line);
        if (words.empty())
            continue;
        auto fail = [&](const Word& at, std::string message) {
            scenario.diagnostics.push_back(
                {lang::Severity::Error, lineNumber, at.column, std::move(message)});
        };
        ScenarioStep step;
        step.line = lineNumber;
        for (std::size_t i = 0; i < words.size(); ++i)
            step.text += (i ? " " : "") + std::string(words[i].text);
        const std::string verb = lang::toLower(words[0].text);
        auto expectCount = [&](std::size_t count, const char* form) {
            if (words.size() == count)
                return true;
            fail(words.size() > count ? words[count] : words.back(),
                 std::string(words.size() > count
                                 ? "unexpected '" + std::string(words[count].text) +
                                       "'; the form is "
                                 : "missing argument; the form is ") +
                     form);
            return false;
        };
        auto operand = [&](const Word& word) {
            std::string error;
            if (!names.resolve(word.text, step.operand, error)) {
                fail(word, error);
                return false;
            }
            return true;
        };
        auto value = [&](const Word& word) {
            const Number read = parseInteger(word.text, step.value);
            if (read == Number::Malformed) {
                fail(word, "expected a number, found '" + std::string(word.text) + "'");
                return false;
            }
            const ValueRange range = valueRange(step.operand);
            if (read == Number::OutOfRange || step.value < range.low || step.value > range.high) {
                fail(word, lang::toString(step.operand) + " is " + range.what + ": its value is " +
                               rangeText(range));
                return false;
            }
            return true;
        };
        // Virtual time the step takes, within the scenario's bound.
        auto addTime = [&](const Word& word, std::int64_t ms) {
            if (ms > kMaxVirtualMs - virtualMs) {
                fail(word, "a scenario runs at most 30 days of virtual time; this line would "
                           "pass that");
                return false;
            }
            virtualMs += ms;
            return true;
        };
        auto duration = [&](const Word& word, std::int64_t& ms) {
            if (!parseDuration(word.text, ms)) {
                fail(word, "expected a duration such as 10ms, 2.5s, 2s50 or 1min, found '" +
                               std::string(word.text) + "'");
                return false;
            }
            return true;
        };
        bool ok = false;
        if (verb == "set") {
            step.kind = ScenarioStep::Kind::Set;
            ok = expectCount(3, "set OPERAND VALUE");
            if (ok) {
                std::string error;
                ok = names.resolveChannel(words[1].text, step.operand, step.channel, error);
                if (!ok)
                    fail(words[1], error);
                ok = ok && value(words[2]);
            }
        } else if (verb == "release") {
            step.kind = ScenarioStep::Kind::Release;
            ok = expectCount(2, "release OPERAND") && operand(words[1]);
        } else if (verb == "run") {
            step.kind = ScenarioStep::Kind::Run;
            ok = expectCount(2, "run DURATION") && duration(words[1], step.durationMs) &&
                 addTime(words[1], step.durationMs);
            timeStarted = true;
        } else if (verb == "scans") {
            step.kind = ScenarioStep::Kind::Scans;
            ok = expectCount(2, "scans N");
            const Number read = ok ? parseInteger(words[1].text, step.count) : Number::Malformed;
            if (ok && (read == Number::Malformed || step.count < 0 || words[1].text[0] == '-')) {
                fail(words[1],
                     "expected a number of scans, found '" + std::string(words[1].text) + "'");
                ok = false;
            } else if (ok) {
                // A count too large to read is past the bound as well.
                const std::int64_t most = (kMaxVirtualMs - virtualMs) / cycleMs;
                ok = addTime(words[1], read == Number::OutOfRange || step.count > most
                                           ? kMaxVirtualMs + 1
                                           : step.count * cycleMs);
            }
            timeStarted = true;
        } else if (verb == "expect") {
            step.kind = ScenarioStep::Kind::Expect;
            expects = true;
            if (words.size() == 5 || words.size() == 3) {
                ok = operand(words[1]) && value(words[2]);
                if (ok && words.size() == 5) {
                    if (lang::toLower(words[3].text) != "within") {
                        fail(words[3],
                             "expected 'within', found '" + std::string(words[3].text) + "'");
                        ok = false;
                    } else {
                        ok = duration(words[4], step.durationMs) &&
                             addTime(words[4], step.durationMs);
                        timeStarted = true;
                    }
                }
            } else {
                expectCount(words.size() < 3 ? 3 : 5, "expect OPERAND VALUE [within DURATION]");
            }
        } else if (verb == "disconnect" || verb == "connect") {
            step.kind =
                verb == "connect" ? ScenarioStep::Kind::Connect : ScenarioStep::Kind::Disconnect;
            ok = expectCount(2, verb == "connect" ? "connect UNIT" : "disconnect UNIT");
            std::int64_t station = -1;
            if (ok &&
                (parseInteger(words[1].text, station) != Number::Ok ||
                 !names.hasStation(static_cast<int>(station)) || station < 0 || station > 31)) {
                fail(words[1], "expected the number of one of the project's units, found '" +
                                   std::string(words[1].text) + "'");
                ok = false;
            }
            step.value = station;
        } else if (verb == "cycle") {
            step.kind = ScenarioStep::Kind::Cycle;
            ok = expectCount(2, "cycle DURATION") && duration(words[1], step.durationMs);
            if (ok && timeStarted) {
                fail(words[0], "cycle must come before the first run");
                ok = false;
            }
            if (ok && (step.durationMs < kMinCycleMs || step.durationMs > kMaxCycleMs)) {
                fail(words[1], "the scan cycle must be 1ms to 10s");
                ok = false;
            }
            if (ok)
                cycleMs = step.durationMs;
        } else {
            fail(words[0], "unknown line '" + std::string(words[0].text) +
                               "'; expected set, release, run, scans, expect, cycle, "
                               "disconnect or connect");
        }
        if (ok)
            scenario.steps.push_back(std::move(step));
    }
    if (!expects && scenario.diagnostics.empty())
        scenario.diagnostics.push_back(
            {lang::Severity::Error, 1, 1, "no expectation: a scenario must check something"});
    return scenario;
}

} // namespace rs::sim
