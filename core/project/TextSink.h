// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <string_view>

namespace rs::project {

// Where text goes as it is made, piece by piece: a large output (the 21 MB of
// Intel HEX of a 32-unit image) reaches its file without a copy of the whole
// of it in memory (issue 23).
using TextSink = std::function<void(std::string_view piece)>;

} // namespace rs::project
