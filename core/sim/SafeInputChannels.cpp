// SPDX-License-Identifier: GPL-3.0-or-later
#include "SafeInputChannels.h"

namespace rs::sim {

using project::ChannelMonitoring;

SafeInputChannels::SafeInputChannels(ChannelMonitoring monitoring, std::int64_t timeLimitMs)
    : m_monitoring(monitoring), m_timeLimitMs(timeLimitMs) {}

void SafeInputChannels::setChannel(int channel, bool closed) {
    m_channels[channel == 2 ? 1 : 0] = closed;
}

bool SafeInputChannels::channel(int channel) const {
    return m_channels[channel == 2 ? 1 : 0];
}

void SafeInputChannels::powerOn() {
    m_channels[0] = m_channels[1] = false;
    m_state = State::Open;
    m_since = 0;
    m_input = false;
}

bool SafeInputChannels::simultaneous() const {
    return m_monitoring == ChannelMonitoring::Simultaneous ||
           m_monitoring == ChannelMonitoring::SimultaneousDebounce;
}

void SafeInputChannels::bothClosed(std::int64_t nowMs) {
    switch (m_monitoring) {
    case ChannelMonitoring::MonitoringDebounce:
        // Bounces are allowed for the time limit from both channels closing.
        m_state = State::Window;
        m_since = nowMs;
        break;
    case ChannelMonitoring::Simultaneous:
        m_state = nowMs - m_since > m_timeLimitMs ? State::Locked : State::On;
        break;
    default:
        m_state = State::On;
        break;
    }
}

void SafeInputChannels::update(std::int64_t nowMs) {
    const bool both = m_channels[0] && m_channels[1];
    const bool none = !m_channels[0] && !m_channels[1];
    if (m_monitoring == ChannelMonitoring::None) {
        m_input = both;
        return;
    }
    switch (m_state) {
    case State::Open:
        if (none)
            break;
        m_since = nowMs;
        if (m_monitoring == ChannelMonitoring::SimultaneousDebounce)
            m_state = State::Window; // bounces allowed for the time limit from the first closing
        else if (both)
            bothClosed(nowMs);
        else
            m_state = State::Closing;
        break;
    case State::Closing:
        if (none)
            m_state = State::Open;
        else if (both)
            bothClosed(nowMs);
        else if (simultaneous() && nowMs - m_since > m_timeLimitMs)
            m_state = State::Locked;
        break;
    case State::Window:
        if (nowMs - m_since > m_timeLimitMs)
            m_state = both ? State::On : none ? State::Open : State::Locked;
        break;
    case State::On:
        if (!both)
            m_state = none ? State::Open : State::Locked;
        break;
    case State::Locked:
        if (none)
            m_state = State::Open;
        break;
    }
    m_input = both && (m_state == State::On || m_state == State::Window);
}

} // namespace rs::sim
