// SPDX-License-Identifier: GPL-3.0-or-later
#include "BlockLibrary.h"

#include <algorithm>

namespace rs::blocks {

namespace {

char lower(char c) {
    return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

template <typename T> const T* findNamed(const std::vector<T>& items, std::string_view name) {
    const auto found = std::find_if(items.begin(), items.end(),
                                    [name](const T& item) { return sameName(item.name, name); });
    return found == items.end() ? nullptr : &*found;
}

} // namespace

bool sameName(std::string_view a, std::string_view b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](char x, char y) { return lower(x) == lower(y); });
}

const std::string& Description::in(std::string_view language) const {
    if (language == "sv" && !swedish.empty())
        return swedish;
    if (language == "de" && !german.empty())
        return german;
    return english;
}

const Pin* BlockDefinition::findPin(std::string_view pinName) const {
    return findNamed(pins, pinName);
}

const PrivateVariable* BlockDefinition::findPrivate(std::string_view privateName) const {
    return findNamed(privates, privateName);
}

const BlockDefinition* BlockLibrary::findBlock(std::string_view blockName) const {
    return findNamed(blocks, blockName);
}

} // namespace rs::blocks
