// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string_view>
#include <vector>

namespace rs::ui {

// The keywords of property files: the verbs, `cycle`, and what may follow `->`.
const std::vector<std::string_view>& propertyKeywords();
// Case does not matter, as for the verbs.
bool isPropertyKeyword(std::string_view word);
// `within` and `cycle`, which a duration follows.
bool isDurationKeyword(std::string_view word);

} // namespace rs::ui
