// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Ast.h"
#include "project/Project.h"

#include <string>

namespace rs::test {

// A one-unit project whose PLC code step holds `body`, read with names
// resolved. Statements may use the names EStop (I0.12) and Lamp (Q0.17).
project::Project projectWithCode(const std::string& body);

// The PLC code step of projectWithCode(body).
lang::Step stepWithCode(const std::string& body);

// The canonical text of a step's lines.
std::string printLines(const std::vector<lang::Line>& lines);

} // namespace rs::test
