// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Program.h"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

// Runs a checked PL110 program scan by scan on virtual time (docs/pl110.md,
// "Scan"): INIT once before the first scan, then MAIN every scan, timers in
// their time bases, counters' contacts at the end of the scan, the special
// markers of the datasheet that matter for logic.
namespace rs::pl110 {

// The PL110's memory: every area's words, and the timers' and counters'
// contacts, which live beside their values.
struct Memory {
    std::array<std::vector<std::uint16_t>, kAreaCount> words;
    std::array<bool, 48> timerContacts{};
    std::array<bool, 16> counterContacts{};

    Memory();
    bool bit(const Address& address) const;
    void setBit(const Address& address, bool value);
    // The signed value of a word or double word (VDn: VWn high, VWn+1 low).
    std::int32_t value(const Address& address) const;
    // Stores the low 16 bits (a word) or all 32 (a double word).
    void setValue(const Address& address, std::int64_t value);
};

// What one rung did in the last scan, for live colouring: numbered as the
// ladder numbers its elements (0 the output, 1.. the condition in pre-order).
struct RungMarks {
    bool ran = false;
    bool energised = false;           // power reached the output
    std::vector<std::uint8_t> power;  // by element: power at its right side
    std::vector<std::uint8_t> states; // by element: sim::ElementState bits
};

class ScanEngine {
public:
    // The program must have passed checkProgram.
    explicit ScanEngine(Program program, int cycleMs = 10);

    // Power on: memory cleared, the special markers' start values, no forces.
    void reset();
    // One scan cycle; the first also runs INIT.
    void scan();
    void setCycleMs(int cycleMs);

    // Any variable: a bit as 0 or 1, a word or double word as its signed value.
    std::int64_t value(const Address& address) const;
    // Inputs (I, AI) take the value, as from the terminals; any other
    // variable is forced.
    void set(const Address& address, std::int64_t value);
    // A forced variable holds its value: the program reads it and its writes
    // are undone as soon as the output that made them is done.
    void force(const Address& address, std::int64_t value);
    void release(const Address& address);

    Memory& memory() { return m_memory; }
    const Memory& memory() const { return m_memory; }
    std::uint64_t scans() const { return m_scans; }
    // By rung, INIT's then MAIN's in file order: rung n (from 1) is marks()[n - 1].
    const std::vector<RungMarks>& marks() const { return m_marks; }
    std::int64_t timeMs() const { return m_timeMs; }
    int cycleMs() const { return m_cycleMs; }

private:
    struct TimerState {
        int remainderMs = 0; // time not yet a whole unit of the base
        bool wasOn = false;
        bool counting = false; // TOFF: running down after the coil went off
    };
    struct RungState {
        std::vector<std::uint8_t> edges; // by element number: the power last seen
        bool coilWasOn = false;          // B coils and counter inputs count edges
    };

    void runLines(const std::vector<Line>& lines, std::vector<RungState>& states,
                  std::size_t firstMark);
    bool evaluate(const Circuit& circuit, bool power, RungState& state, int& node,
                  RungMarks& marks);
    void output(const Output& out, bool power, RungState& state);
    // The timer's contact, and whether it is counting.
    std::pair<bool, bool> timer(const Output& out, bool power);
    void counter(const Output& out, bool power, RungState& state);
    std::int32_t read(const Value& value) const;
    void specialMarkersAtScanStart();
    void countersAtScanEnd();
    // The output's own state after its rung: its variable 1, a timer counting.
    std::uint8_t outputState(const Output& out, bool power) const;
    void applyForces();

    Program m_program;
    int m_cycleMs;
    Memory m_memory;
    std::vector<RungState> m_init;
    std::vector<RungState> m_main;
    std::array<TimerState, 48> m_timers{};
    std::array<std::optional<CounterType>, 16> m_counterTypes{}; // of the counters with coils
    std::map<Address, std::int64_t> m_forces;
    std::vector<RungMarks> m_marks;
    bool m_timerRunning = false; // of the timer coil that ran last
    std::uint64_t m_scans = 0;
    std::int64_t m_timeMs = 0;
};

} // namespace rs::pl110
