// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Address.h"

#include <optional>
#include <string>
#include <string_view>

namespace rs::lang {

// Checks a symbolic name against the manual's rules (Unicode letters, digits
// and '_', not first; '.' with instruction set 2 only) and against words the
// language already uses. Returns the reason it is refused, or nothing.
std::optional<std::string> checkSymbolicName(std::string_view name, int instructionSet);

// Names compare without regard to case, like everything in the language.
std::string foldName(std::string_view name);

// The system memories and registers the manuals name (SM_SysInit, SR_Remain, ...),
// for the given unit; an invalid address when the name is not one of them.
Address systemName(std::string_view name, int unit);

} // namespace rs::lang
