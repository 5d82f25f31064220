// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "project/ProjectFile.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

// What every project-text fuzz target asks: reading never crashes, and a
// project that reads without errors prints to text that reads back without
// errors and prints the same again. Aborts, for the fuzzer, when it does not.
inline void checkProjectRoundTrip(std::string_view text) {
    const auto result = rs::project::readProject(text);
    if (!result.ok())
        return;
    const std::string printed = rs::project::writeProject(result.project);
    const auto again = rs::project::readProject(printed);
    if (!again.ok()) {
        std::fprintf(stderr, "canonical text does not read back: %d:%d: %s\n",
                     again.diagnostics.front().line, again.diagnostics.front().column,
                     again.diagnostics.front().message.c_str());
        std::abort();
    }
    if (rs::project::writeProject(again.project) != printed) {
        std::fprintf(stderr, "canonical text is not stable\n");
        std::abort();
    }
}
