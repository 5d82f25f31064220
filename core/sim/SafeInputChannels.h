// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "project/AsiOptions.h"

#include <cstdint>

namespace rs::sim {

// The two channels of one dual-channel AS-i safe input slave, and the input
// the unit reads from them by the slave's channel monitoring (manual Part 1,
// 7.1.4.2). docs/simulator.md, "AS-i safe input slaves", states the rules.
class SafeInputChannels {
public:
    SafeInputChannels(project::ChannelMonitoring monitoring, std::int64_t timeLimitMs);

    void setChannel(int channel, bool closed); // channel 1 or 2
    bool channel(int channel) const;
    // Takes the channels as they stand at virtual time `nowMs`, before a scan.
    void update(std::int64_t nowMs);
    bool input() const { return m_input; }
    // A channel opened alone, or closed too late: the input stays off until
    // both channels have opened.
    bool fault() const { return m_state == State::Locked; }
    // Both channels open, nothing pending.
    void powerOn();

private:
    enum class State : std::uint8_t {
        Open,    // both channels seen open: ready to close
        Closing, // one channel closed, the other not yet
        Window,  // a debounce window: the input is both channels, bounces allowed
        On,      // both closed
        Locked,  // a channel fault
    };

    void bothClosed(std::int64_t nowMs);
    bool simultaneous() const;

    project::ChannelMonitoring m_monitoring;
    std::int64_t m_timeLimitMs;
    bool m_channels[2] = {false, false};
    State m_state = State::Open;
    std::int64_t m_since = 0; // the first closing, or the start of a debounce window
    bool m_input = false;
};

} // namespace rs::sim
