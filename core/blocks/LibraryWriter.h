// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "BlockLibrary.h"

#include <string>

namespace rs::blocks {

// The canonical text of a library: fixed key order and indentation, so a
// library written by the IDE diffs line by line, and reading it back gives
// the same model. Comments of a hand-written file are not part of the model
// and are not written.
std::string writeLibrary(const BlockLibrary& library);

} // namespace rs::blocks
