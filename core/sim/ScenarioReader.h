// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Scenario.h"
#include "lang/TextCase.h"
#include "project/Utf8Text.h"

#include <string>
#include <string_view>
#include <vector>

// Reading a scenario (../shared/spec/scenario.md) for any target. The
// vocabulary says what the operand words mean: Pluto's OperandNames, the
// PL110's pl110::ScenarioNames. It provides
//   using Operand = ...;
//   bool resolve(std::string_view word, Operand&, std::string& error) const;
//   bool resolveChannel(std::string_view word, Operand&, int& channel, std::string& error) const;
//   bool hasStation(int station) const;    // connect and disconnect
//   ValueRange range(const Operand&) const;
//   std::string spelling(const Operand&) const;
namespace rs::sim {

namespace scenario_text {

struct Word {
    std::string_view text;
    int column;
};

// Columns count characters, not bytes.
int columnAt(std::string_view line, std::size_t offset);
std::vector<Word> splitWords(std::string_view line);

enum class Number { Ok, Malformed, OutOfRange };
Number parseInteger(std::string_view text, std::int64_t& value);
std::string rangeText(const ValueRange& range);

} // namespace scenario_text

template <class Vocabulary>
BasicScenario<typename Vocabulary::Operand> readScenario(std::string_view text,
                                                         const Vocabulary& names) {
    using Step = BasicScenarioStep<typename Vocabulary::Operand>;
    using namespace scenario_text;
    BasicScenario<typename Vocabulary::Operand> scenario;
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
        Step step;
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
            const ValueRange range = names.range(step.operand);
            if (read == Number::OutOfRange || step.value < range.low || step.value > range.high) {
                fail(word, names.spelling(step.operand) + " is " + range.what + ": its value is " +
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
            step.kind = Step::Kind::Set;
            ok = expectCount(3, "set OPERAND VALUE");
            if (ok) {
                std::string error;
                ok = names.resolveChannel(words[1].text, step.operand, step.channel, error);
                if (!ok)
                    fail(words[1], error);
                ok = ok && value(words[2]);
            }
        } else if (verb == "release") {
            step.kind = Step::Kind::Release;
            ok = expectCount(2, "release OPERAND") && operand(words[1]);
        } else if (verb == "run") {
            step.kind = Step::Kind::Run;
            ok = expectCount(2, "run DURATION") && duration(words[1], step.durationMs) &&
                 addTime(words[1], step.durationMs);
            timeStarted = true;
        } else if (verb == "scans") {
            step.kind = Step::Kind::Scans;
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
            step.kind = Step::Kind::Expect;
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
            step.kind = verb == "connect" ? Step::Kind::Connect : Step::Kind::Disconnect;
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
            step.kind = Step::Kind::Cycle;
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
