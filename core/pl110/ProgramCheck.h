// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Program.h"
#include "lang/Diagnostic.h"

// What the PL110 target allows where (docs/pl110.md, "Checks"): each area's
// access, writes only where the datasheet allows them, timer and counter
// numbers used once per meaning, constants that fit. A program without errors
// is what the scan engine runs.
namespace rs::pl110 {

lang::Diagnostics checkProgram(const Program& program);

// Special-marker bits and words the program and Modbus only read (datasheet 2.1.2).
bool isReadOnlySpecial(const Address& address);

} // namespace rs::pl110
