// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "AndGraph.h"
#include "Word.h"
#include "compiler/Image.h"

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

// One scan cycle of a whole project as a circuit: the state the simulator
// keeps (every variable the programs write, edge memories, timers in ticks,
// active steps, what each unit last put on the bus) and the inputs of the
// scan in, the state after the scan out. Built from the compiled images with
// the meaning the engine gives each instruction (docs/prove.md, "The model").
namespace rs::prove {

struct StateBit {
    Lit current;  // a variable of the graph
    Lit next;     // the value after the scan
    bool initial; // at power on
};

// An input of the scan: what a scenario sets to give it its value (no
// address: a value the model leaves free that no scenario sets).
struct ScanInput {
    lang::Address address;
    Word word; // variables of the graph; a bit is one, a number 16 or 32
    bool bit = false;
};

class ScanModel {
public:
    ScanModel(const std::vector<compiler::UnitImage>& images, int cycleMs);
    ~ScanModel();
    ScanModel(const ScanModel&) = delete;
    ScanModel& operator=(const ScanModel&) = delete;

    AndGraph& graph() { return m_graph; }
    const AndGraph& graph() const { return m_graph; }
    WordBuilder& words() { return m_words; }
    int cycleMs() const { return m_cycleMs; }

    // What the model leaves free instead of computing it, as sentences ("unit
    // 0 line 12: the outputs of Ext_Sig"): a proof holds whatever values
    // they take; a counterexample may need values the simulator never gives.
    const std::vector<std::string>& abstractions() const { return m_abstractions; }

    // A variable's value at the end of the scan, as Simulation::value reads
    // it (S<u>.<s>: the active step, -1 without the sequence). Reading an
    // input the programs do not read adds it to the inputs.
    Word valueAfterScan(const lang::Address& address);

    // More state: a word whose value after the scan is set with setNext.
    Word addState(int width, std::int64_t initial);
    void setNext(const Word& current, const Word& next);

    const std::vector<StateBit>& state() const { return m_state; }
    // The state bit whose current value is `node`, or -1.
    int stateOf(std::uint32_t node) const;
    // Every node the literals depend on through any number of scans (at a
    // state bit, its value after the scan too), node 0 first.
    std::vector<std::uint32_t> cone(const std::vector<Lit>& roots) const;
    // The state as words, as added: a bit is a word of one.
    const std::vector<Word>& stateWords() const { return m_stateWords; }
    // Each timer's counter and how far it counts.
    const std::vector<std::pair<Word, std::int64_t>>& timerCounters() const {
        return m_timerCounters;
    }
    const std::vector<ScanInput>& inputs() const { return m_inputs; }

    // What the differential test compares with the engine: each timer's
    // counter and bits, by unit and slot.
    struct TimerState {
        Word ticks;
        Lit lastInput;
        Lit running;
        Lit ranLast;
        std::int64_t capTicks;
    };
    std::optional<TimerState> timerState(int station, int slot) const;

    // The invariants the compiler knows: true in every reachable state, to be
    // proved with the property (a timer's counter within its cap, a sequence
    // in one of its steps). Literals over the current state.
    const std::vector<Lit>& structuralInvariants() const { return m_invariants; }

private:
    struct Unit;
    void buildScan();

    AndGraph m_graph;
    WordBuilder m_words{m_graph};
    int m_cycleMs;
    std::vector<std::unique_ptr<Unit>> m_units;
    std::vector<StateBit> m_state;
    std::vector<Word> m_stateWords;
    std::vector<std::pair<Word, std::int64_t>> m_timerCounters;
    std::vector<std::int32_t> m_stateOfNode; // node -> index in m_state, or -1
    std::vector<ScanInput> m_inputs;
    std::vector<std::string> m_abstractions;
    std::vector<Lit> m_invariants;
    Lit m_firstScan = kFalse;
    std::map<int, Word> m_timeOfDay; // period -> time modulo it at the start of the scan

    friend class ScanBuilder;
};

} // namespace rs::prove
