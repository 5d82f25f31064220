// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace rs::lang {

// 1-based line and column of a token in its file; 0 means "not from a file".
struct SourceLocation {
    int line = 0;
    int column = 0;

    // A node means the same wherever it was written, so comparing two syntax
    // trees (for example a parsed tree and a generated one) ignores positions.
    friend bool operator==(SourceLocation, SourceLocation) { return true; }
};

} // namespace rs::lang
