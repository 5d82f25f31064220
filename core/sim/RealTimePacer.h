// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>

namespace rs::sim {

// Keeps virtual time in step with the wall clock times a speed factor, for a
// simulation shown live. The caller asks, on each tick of its own timer, how
// many scans to run now. When the machine cannot keep up, the pacer drops the
// backlog instead of running ever longer bursts.
class RealTimePacer {
public:
    // speed: 1 real time, 10 ten times faster; 0 or less: as fast as possible.
    explicit RealTimePacer(double speed = 1.0) : m_speed(speed) {}

    // Starts (or restarts) pacing at this wall-clock time and virtual time.
    void start(std::int64_t wallMs, std::int64_t virtualMs);
    // A new speed takes effect from now on, without a jump in virtual time.
    void setSpeed(double speed, std::int64_t wallMs, std::int64_t virtualMs);
    double speed() const { return m_speed; }

    // Scans to run now, at most maxScans.
    int scansDue(std::int64_t wallMs, std::int64_t virtualMs, int cycleMs, int maxScans);

private:
    double m_speed;
    std::int64_t m_wallStart = 0;
    std::int64_t m_virtualStart = 0;
};

} // namespace rs::sim
