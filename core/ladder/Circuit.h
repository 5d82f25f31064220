// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Element.h"
#include "SeriesParallel.h"

namespace rs::ladder {

// A Pluto rung's condition: the language's expression tree has the same
// shape, series is AND and parallel is OR.
using Circuit = SeriesParallel<Element>;

} // namespace rs::ladder
