// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>

namespace rs::sim {

// Per instruction, what the last scan did: not run (its step was not
// active), run with the power off after it, or run with the power on.
enum class Conduction : std::uint8_t { NotRun = 0, Off = 1, On = 2 };

// Per instruction, the state of its element on its own, whatever power
// reached it, as the last scan read it: bits of a byte, 0 when none applies
// (a load, a branch, a rung's start) or the instruction did not run.
enum ElementState : std::uint8_t {
    // A contact or edge passes power (its negation included: NC with its bit
    // 0); a comparison or timer box is true (before a negation bubble: the
    // comparison holds, the timer's output is on); a bit output's variable is
    // 1 after the scan (forced, or set elsewhere, too); a jump, sequence
    // reset or arithmetic output had power.
    Closed = 1,
    // A timer is counting its time (on-delay: input on and not elapsed;
    // pulse: the pulse is on; off-delay: input off and not elapsed).
    Running = 2,
};

} // namespace rs::sim
