// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "compiler/Image.h"

#include <string>
#include <vector>

namespace rs::bench {

// C++ source that does what the simulator's engine does with these images,
// one straight-line function per unit: the "native" side of the simulator
// benchmark. It defines `void rs::native::scanPlant(rs::native::Plant&,
// std::int64_t timeMs, int cycleMs)`. Forcing and conduction snapshots are
// left out: the benchmark compares the scans alone.
std::string generateNativeCode(const std::vector<compiler::UnitImage>& images);

} // namespace rs::bench
