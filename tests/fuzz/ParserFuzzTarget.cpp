// SPDX-License-Identifier: GPL-3.0-or-later
#include "project/ProjectFile.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

// Any input: reading never crashes. A project that reads without errors
// prints to text that reads back without errors and prints the same again.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    auto result = rs::project::readProject(text);
    if (!result.ok())
        return 0;
    const std::string printed = rs::project::writeProject(result.project);
    auto again = rs::project::readProject(printed);
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
    return 0;
}
