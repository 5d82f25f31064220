// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Address.h"
#include "lang/Diagnostic.h"
#include "project/Project.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

// Scenario files (.scn): a user's test of a program on virtual time, as
// ../shared/spec/scenario.md defines them.
namespace rs::sim {

// One line of a scenario. `OperandType` is the target's address: Pluto's
// lang::Address, the PL110's pl110::Address; the rest is every target's.
template <class OperandType> struct BasicScenarioStep {
    // Disconnect and Connect take unit `value` off the bus and put it back.
    enum class Kind {
        Set,
        Release,
        Run,
        Scans,
        Expect,
        Cycle,
        Disconnect,
        Connect
    } kind = Kind::Run;
    OperandType operand;
    std::int64_t value = 0;
    std::int64_t durationMs = 0; // Run, Cycle; Expect with `within` (0 without)
    std::int64_t count = 0;      // Scans
    int channel = 0;             // Set of one channel (1 or 2) of a safe AS-i slave; 0 the operand
    int line = 0;
    std::string text; // the line as written, without its comment
};

template <class OperandType> struct BasicScenario {
    using Step = BasicScenarioStep<OperandType>;
    std::vector<Step> steps;
    lang::Diagnostics diagnostics; // syntax errors: the scenario does not run
};

using ScenarioStep = BasicScenarioStep<lang::Address>;
using Scenario = BasicScenario<lang::Address>;

// What a scenario may ask for: longer cycles or runs cannot be meant, and
// would keep the simulator busy for days of real time.
inline constexpr std::int64_t kMinCycleMs = 1;
inline constexpr std::int64_t kMaxCycleMs = 10'000;
inline constexpr std::int64_t kMaxVirtualMs = 30LL * 24 * 60 * 60 * 1000; // 30 days

// What an operand can hold, which a `set` or `expect` must stay within: a
// value outside would be cut to fit, and the scenario would test something
// other than what it says.
struct ValueRange {
    std::int64_t low;
    std::int64_t high;
    const char* what; // "a bit", "a register", ...
};
ValueRange valueRange(const lang::Address& address);

// Names a scenario may use: the project's symbolic names, and the system
// names when the project has one unit. The scenario reader's vocabulary for
// Pluto (ScenarioReader.h).
class OperandNames {
public:
    using Operand = lang::Address;

    explicit OperandNames(const project::Project& project);
    // The address of a name or address word; an error message otherwise.
    bool resolve(std::string_view word, lang::Address& address, std::string& error) const;
    bool hasStation(int station) const;
    // Whether unit `station`'s program has sequence `sequence` (0: its PLC code).
    bool hasSequence(int station, int sequence) const;
    // The declared name of the variable at `address`, as declared; empty when
    // it has none or its name is ambiguous.
    std::string nameOf(const lang::Address& address) const;
    // As resolve(), and OPERAND.ch1 or OPERAND.ch2 for one channel of a safe
    // input slave the AS-i Options page defines: `channel` is 1 or 2, else 0.
    bool resolveChannel(std::string_view word, lang::Address& address, int& channel,
                        std::string& error) const;
    ValueRange range(const lang::Address& address) const { return valueRange(address); }
    std::string spelling(const lang::Address& address) const { return lang::toString(address); }

private:
    struct Entry {
        lang::Address address;
        bool ambiguous = false;
        std::string spelling; // as declared
    };
    std::vector<std::pair<std::string, Entry>> m_names; // folded name -> address
    std::vector<int> m_stations;
    std::vector<std::pair<int, int>> m_sequences; // (station, sequence), sorted
    std::vector<lang::Address> m_channelSlaves;
};

// Lines end at LF, CRLF or a lone CR; a leading byte-order mark is skipped.
// Besides syntax, refuses values out of their operand's range, a cycle outside
// kMinCycleMs..kMaxCycleMs, virtual time past kMaxVirtualMs (each step's and
// the scenario's in total), text that is not UTF-8, and a scenario that
// expects nothing.
Scenario parseScenario(std::string_view text, const OperandNames& names);

// "10ms", "2.5s", "2s50" (the language's notation), "1min"; false when malformed.
bool parseDuration(std::string_view text, std::int64_t& ms);

} // namespace rs::sim
