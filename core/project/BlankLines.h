// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Ast.h"

namespace rs::project {

// Brings a document's blank lines into the shape the parser gives: no run of
// two, none before the first line or after the last. Edits that insert or
// remove lines end with this, so that writing and reading the project gives
// the same tree back.
void tidyBlankLines(lang::Document& document);
// The same, of the code of one unit, when the rest is in that shape already.
void tidyUnitBlankLines(lang::Document& document, int station);

} // namespace rs::project
