// SPDX-License-Identifier: GPL-3.0-or-later
#include "prove/PropertyWords.h"

#include <algorithm>
#include <cctype>

namespace rs::ui {

namespace {

bool sameWord(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

} // namespace

const std::vector<std::string_view>& propertyKeywords() {
    static const std::vector<std::string_view> words{"always", "never",  "assume", "cover",
                                                     "cycle",  "within", "next"};
    return words;
}

bool isPropertyKeyword(std::string_view word) {
    const auto& words = propertyKeywords();
    return std::any_of(words.begin(), words.end(),
                       [word](std::string_view keyword) { return sameWord(word, keyword); });
}

bool isDurationKeyword(std::string_view word) {
    return sameWord(word, "within") || sameWord(word, "cycle");
}

} // namespace rs::ui
