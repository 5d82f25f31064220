// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectRoundTrip.h"

#include <cstdint>
#include <string>
#include <string_view>

// The ";@" records: each input line becomes one record, placed both in the
// preamble and in a step of a fixed one-unit project, so that the fuzzer
// spends its time on the record reader rather than on finding a valid
// project; then the same round trip as the parser's target.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    std::string records;
    for (std::size_t start = 0; start <= input.size();) {
        std::size_t end = input.find('\n', start);
        if (end == std::string_view::npos)
            end = input.size();
        records += ";@";
        records += input.substr(start, end - start);
        records += '\n';
        start = end + 1;
    }
    const std::string text = "$name Fuzz\n" + records +
                             "! id_pluto:00=000000000000\n! I0.0=Start\n! pgm_pluto:00\nS0.0_0\n" +
                             records + "Q0.0 = Start\n";
    checkProjectRoundTrip(text);
    return 0;
}
