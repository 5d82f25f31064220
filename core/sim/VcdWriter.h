// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <string>
#include <vector>

// A Value Change Dump of any target's variables, which GTKWave opens: the
// first sample is the state at power on, each later one only what changed.
// No dates or paths: the same run gives the same bytes.
namespace rs::sim {

struct VcdSignal {
    std::string scope;     // the module it is shown in: "pluto0", "pl110"
    std::string reference; // its name there: "Q2", "V3_4"
    bool bit = false;      // a wire of 1 bit, else a 32-bit integer
};

class VcdWriter {
public:
    // Signals of one scope stand together.
    explicit VcdWriter(std::vector<VcdSignal> traced);

    // The value of every signal, in the order given to the constructor.
    void sample(std::int64_t timeMs, const std::vector<std::int64_t>& values);
    std::string text(const std::string& title) const;

private:
    std::vector<VcdSignal> m_signals;
    std::vector<std::string> m_ids;
    std::vector<std::int64_t> m_last;
    std::string m_changes;
    bool m_sampled = false;
};

} // namespace rs::sim
