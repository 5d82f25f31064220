// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Diagnostic.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string_view>

// What a fuzz target does when an input breaks a promise: say which, and
// abort, so that libFuzzer keeps the input.
namespace rs::fuzz {

[[noreturn]] inline void fail(const char* what) {
    std::fprintf(stderr, "%s\n", what);
    std::abort();
}

// Every diagnostic points at a line and a column of the text it is about.
inline void requireInside(std::string_view text, const lang::Diagnostics& diagnostics,
                          const char* what) {
    const auto lines = static_cast<int>(std::count(text.begin(), text.end(), '\n') +
                                        std::count(text.begin(), text.end(), '\r')) +
                       1;
    for (const auto& diagnostic : diagnostics)
        if (diagnostic.line < 1 || diagnostic.line > lines || diagnostic.column < 1 ||
            static_cast<std::size_t>(diagnostic.column) > text.size() + 1)
            fail(what);
}

} // namespace rs::fuzz
