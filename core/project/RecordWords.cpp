// SPDX-License-Identifier: GPL-3.0-or-later
#include "RecordWords.h"

#include <charconv>

namespace rs::project {

std::optional<int> wholeNumber(std::string_view word) {
    int value = 0;
    const auto [end, problem] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (word.empty() || problem != std::errc() || end != word.data() + word.size())
        return std::nullopt;
    return value;
}

std::string stationText(int station) {
    return (station < 10 ? "0" : "") + std::to_string(station);
}

} // namespace rs::project
