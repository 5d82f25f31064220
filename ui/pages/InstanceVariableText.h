// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "blocks/InstanceVariables.h"

#include <QString>

#include <map>
#include <vector>

namespace rs::ui {

// How a page says what a block instance uses a variable for: "Pin Channel1
// of block EquivalentInputs (line 4)", "Private variable #fault of block
// EquivalentInputs (line 4)"; the line is of the unit's text.
QString instanceVariableText(const blocks::InstanceVariable& variable);

// Each variable's uses, one a line, by its address.
std::map<lang::Address, QString>
instanceUseTexts(const std::vector<blocks::InstanceVariable>& variables);

} // namespace rs::ui
