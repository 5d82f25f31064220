// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

// What chosen variables did over virtual time, scan by scan, kept as their
// changes only, for any target: the waveform painter and view draw a
// Waveform, and each target's recorder (a BasicWaveformRecorder over its
// addresses) fills one. A sample is stamped as the VCD trace of a scenario
// stamps it: power on at its time, each scan's results at the time the next
// scan starts.
namespace rs::sim {

struct WaveformChange {
    std::int64_t timeMs = 0;
    std::int64_t value = 0;
};

class Waveform {
public:
    virtual ~Waveform() = default;
    virtual std::size_t rows() const = 0;
    // The first is the value when recording began.
    virtual const std::vector<WaveformChange>& changes(std::size_t row) const = 0;
    // The variable's address as its target writes it.
    virtual std::string label(std::size_t row) const = 0;
    // Drawn as a 0/1 trace rather than a band of numbers.
    virtual bool isBit(std::size_t row) const = 0;
    // The time of the first and the last sample; equal when nothing was recorded.
    virtual std::int64_t startMs() const = 0;
    virtual std::int64_t endMs() const = 0;
};

template <class Operand> class BasicWaveformRecorder : public Waveform {
public:
    using Change = WaveformChange;
    struct Trace {
        Operand address;
        std::vector<Change> changes; // the first is the value when recording began
    };

    // Records the variable from the next sample on, or from the last one
    // with its value then; false when it is recorded already.
    bool add(const Operand& address, std::optional<std::int64_t> valueNow = std::nullopt) {
        if (contains(address))
            return false;
        m_traces.push_back({address, {}});
        if (valueNow && m_sampled)
            m_traces.back().changes.push_back({m_endMs, *valueNow});
        return true;
    }
    void remove(const Operand& address) {
        std::erase_if(m_traces, [&](const Trace& trace) { return trace.address == address; });
    }
    // Stops recording every variable: a large run's traces cost time each scan.
    void removeAll() { m_traces.clear(); }
    bool contains(const Operand& address) const {
        return std::any_of(m_traces.begin(), m_traces.end(),
                           [&](const Trace& trace) { return trace.address == address; });
    }
    // Forgets what was recorded (power on again, a new run) but keeps the variables.
    void clear() {
        for (Trace& trace : m_traces)
            trace.changes.clear();
        m_sampled = false;
        m_startMs = m_endMs = 0;
    }
    // One sample at `now`: valueOf(address) for every variable.
    template <class ValueOf> void sample(std::int64_t now, const ValueOf& valueOf) {
        if (!m_sampled) {
            m_startMs = now;
            m_sampled = true;
        }
        m_endMs = now;
        for (Trace& trace : m_traces) {
            const std::int64_t value = valueOf(trace.address);
            if (trace.changes.empty() || trace.changes.back().value != value)
                trace.changes.push_back({now, value});
        }
    }

    const std::vector<Trace>& traces() const { return m_traces; }
    bool isEmpty() const { return !m_sampled; }

    // The recorded variables in address order, as a VCD lists them.
    std::vector<Operand> sortedAddresses() const {
        std::vector<Operand> addresses;
        for (const Trace* trace : sorted())
            addresses.push_back(trace->address);
        return addresses;
    }
    // Every change replayed in time order: sample(timeMs, values) gets the
    // values of all variables then, in sortedAddresses() order. A variable
    // added during the run has its first recorded value before that.
    template <class Sample> void replay(const Sample& sample) const {
        const std::vector<const Trace*> order = sorted();
        std::vector<std::int64_t> times;
        for (const Trace* trace : order)
            for (const Change& change : trace->changes)
                times.push_back(change.timeMs);
        std::sort(times.begin(), times.end());
        times.erase(std::unique(times.begin(), times.end()), times.end());
        std::vector<std::size_t> next(order.size(), 0);
        std::vector<std::int64_t> values(order.size(), 0);
        for (std::size_t i = 0; i < order.size(); ++i)
            if (!order[i]->changes.empty())
                values[i] = order[i]->changes.front().value;
        for (std::int64_t time : times) {
            for (std::size_t i = 0; i < order.size(); ++i) {
                const auto& changes = order[i]->changes;
                while (next[i] < changes.size() && changes[next[i]].timeMs <= time)
                    values[i] = changes[next[i]++].value;
            }
            sample(time, values);
        }
    }

    std::size_t rows() const override { return m_traces.size(); }
    const std::vector<WaveformChange>& changes(std::size_t row) const override {
        return m_traces[row].changes;
    }
    std::int64_t startMs() const override { return m_startMs; }
    std::int64_t endMs() const override { return m_endMs; }

private:
    std::vector<const Trace*> sorted() const {
        std::vector<const Trace*> order;
        for (const Trace& trace : m_traces)
            order.push_back(&trace);
        std::sort(order.begin(), order.end(),
                  [](const Trace* a, const Trace* b) { return a->address < b->address; });
        return order;
    }

    std::vector<Trace> m_traces;
    std::int64_t m_startMs = 0;
    std::int64_t m_endMs = 0;
    bool m_sampled = false;
};

} // namespace rs::sim
