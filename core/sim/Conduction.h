// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>

namespace rs::sim {

// Per instruction, what the last scan did: not run (its step was not
// active), run with the power off after it, or run with the power on.
enum class Conduction : std::uint8_t { NotRun = 0, Off = 1, On = 2 };

} // namespace rs::sim
