// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Invocation.h"

namespace rs::cli {

// "blocks list [--lib NAME|FILE]...": one line per block of the libraries
// found (blocks.md). "blocks show NAME": the block's pins, private
// variables, timers, description (--language en|sv|de) and body. A --lib
// that names a file adds that user library; one that names a library
// restricts the list (and the search for NAME) to it.
int runBlocks(const Invocation& invocation);

} // namespace rs::cli
