// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>

namespace rs::sim {

// One timer occurrence: the rules of docs/simulator.md in one place, used by
// the engine and by the benchmark's native translation alike.
struct Timer {
    std::uint64_t lastScan = ~std::uint64_t{0};
    std::int64_t elapsedMs = 0;
    bool lastInput = false;
    bool running = false;
    bool output = false;

    // kind: lang::TimerKind (0 on-delay, 1 pulse, 2 off-delay). `dt` is the
    // virtual time since the previous scan (0 while SM_TimerFreeze holds it).
    // Returns the power the timer passes on.
    bool run(bool input, int kind, std::int64_t presetMs, bool negated, std::int64_t dt,
             std::uint64_t scan) {
        // A timer whose line did not run in the previous scan starts afresh.
        if (lastScan + 1 != scan)
            *this = Timer{};
        lastScan = scan;
        const bool rising = input && !lastInput;
        const bool falling = !input && lastInput;
        if (kind == 0) {
            elapsedMs = input ? (rising ? 0 : elapsedMs + dt) : 0;
            output = input && elapsedMs >= presetMs;
        } else if (kind == 1) {
            if (rising) {
                running = true;
                elapsedMs = 0;
            } else if (input && running) {
                elapsedMs += dt;
            }
            if (!input || elapsedMs >= presetMs)
                running = false;
            output = input && running;
        } else {
            if (input) {
                running = true;
                elapsedMs = 0;
            } else if (running) {
                elapsedMs = falling ? 0 : elapsedMs + dt;
                if (elapsedMs >= presetMs)
                    running = false;
            }
            output = running;
        }
        lastInput = input;
        return negated ? input && !output : output;
    }
};

} // namespace rs::sim
