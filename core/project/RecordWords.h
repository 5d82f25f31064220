// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>
#include <string>
#include <string_view>

// The words the records of the project file share (docs/file-format.md).
namespace rs::project {

// A whole decimal number and nothing else ("12", "-3"); nothing for any other word.
std::optional<int> wholeNumber(std::string_view word);

// A station as the records write it, two digits: "01".
std::string stationText(int station);

} // namespace rs::project
