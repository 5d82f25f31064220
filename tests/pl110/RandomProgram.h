// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "pl110/Program.h"

#include <random>

namespace rs::pl110::testing {

// A random program in the form reading gives: canonical circuits, names
// declared before use, timer and counter values where words are read. With
// `runnable`, only what checkProgram accepts (each timer one coil, counters'
// coils agreeing, writes where writes are allowed).
Program randomProgram(std::mt19937& random, bool runnable);

} // namespace rs::pl110::testing
