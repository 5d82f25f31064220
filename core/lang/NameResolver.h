// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Ast.h"
#include "Diagnostic.h"

#include <vector>

namespace rs::lang {

// Checks every symbolic-name declaration (rules, duplicates, an address named
// twice) where it is written, and resolves every name used in the code to its
// address, rewriting it in its declared spelling. Global names (declared
// before the first "! pgm_pluto") are visible in every unit; names declared
// in a unit's code are visible there only.
Diagnostics resolveNames(Document& document);

// Resolves operands that stand outside the statements of unit `station` (a
// ;@system record's, docs/file-format.md) as its statements' are: a declared
// name, a system name, a bit or half of a named register. An unknown name is
// an error at its operand; the declarations are resolveNames' to check.
Diagnostics resolveOperands(const Document& document, int station,
                            const std::vector<Operand*>& operands);

// Instruction set of each station as the document declares it (type_pluto),
// 2 where it says nothing.
int instructionSetOf(const Document& document, int station);

} // namespace rs::lang
