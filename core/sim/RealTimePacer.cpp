// SPDX-License-Identifier: GPL-3.0-or-later
#include "RealTimePacer.h"

#include <algorithm>

namespace rs::sim {

void RealTimePacer::start(std::int64_t wallMs, std::int64_t virtualMs) {
    m_wallStart = wallMs;
    m_virtualStart = virtualMs;
}

void RealTimePacer::setSpeed(double speed, std::int64_t wallMs, std::int64_t virtualMs) {
    m_speed = speed;
    start(wallMs, virtualMs);
}

int RealTimePacer::scansDue(std::int64_t wallMs, std::int64_t virtualMs, int cycleMs,
                            int maxScans) {
    if (m_speed <= 0)
        return maxScans;
    const double target =
        static_cast<double>(m_virtualStart) + static_cast<double>(wallMs - m_wallStart) * m_speed;
    const double behind = target - static_cast<double>(virtualMs);
    if (behind <= 0)
        return 0;
    const auto due = static_cast<std::int64_t>(behind / cycleMs);
    if (due > maxScans) {
        // Too far behind: run what fits and forget the rest.
        start(wallMs, virtualMs + static_cast<std::int64_t>(maxScans) * cycleMs);
        return maxScans;
    }
    return static_cast<int>(std::max<std::int64_t>(due, 0));
}

} // namespace rs::sim
