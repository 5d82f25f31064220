// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "BlockLibrary.h"
#include "lang/Diagnostic.h"

#include <string_view>

namespace rs::blocks {

struct LibraryReadResult {
    BlockLibrary library;
    lang::Diagnostics diagnostics; // every problem, with its line and column

    bool ok() const { return lang::errorCount(diagnostics) == 0; }
};

// Reads the text of a .rslib file (docs/block-libraries.md). Strict: an
// unknown key, a duplicate name, a value out of its range, a limit passed or
// a body that is not Pluto statements is an error at its line and column;
// the other lines are still read, so every problem is reported at once (a
// block's body is checked once its declarations are good). A library with
// errors must not be used.
LibraryReadResult readLibrary(std::string_view text);

} // namespace rs::blocks
