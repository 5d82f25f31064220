// SPDX-License-Identifier: GPL-3.0-or-later
#include "FuzzFailure.h"

#include "blocks/LibraryReader.h"
#include "blocks/LibraryWriter.h"

#include <cstdint>
#include <string_view>

namespace {

using rs::fuzz::fail;

} // namespace

// Any input: reading never crashes and every problem has its place. A
// library that reads without errors writes a canonical text that reads back
// to the same library and writes the same text again.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const rs::blocks::LibraryReadResult read = rs::blocks::readLibrary(text);
    for (const auto& diagnostic : read.diagnostics)
        if (diagnostic.line < 1 || diagnostic.column < 1)
            fail("a problem without its place");
    if (!read.ok())
        return 0;
    const std::string written = rs::blocks::writeLibrary(read.library);
    const rs::blocks::LibraryReadResult again = rs::blocks::readLibrary(written);
    if (!again.ok())
        fail("the written library does not read back");
    if (!(again.library == read.library))
        fail("the library read back differs");
    if (rs::blocks::writeLibrary(again.library) != written)
        fail("writing is not canonical");
    return 0;
}
