// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <string_view>

namespace rs::lang {

// ASCII case mapping: keywords, addresses and options are ASCII; names keep
// their own letters and are compared with foldName().
std::string toLower(std::string_view text);
std::string toUpper(std::string_view text);

} // namespace rs::lang
