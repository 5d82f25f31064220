// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectRoundTrip.h"

#include <cstdint>
#include <string_view>

// Any project text.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    checkProjectRoundTrip(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
