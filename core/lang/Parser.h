// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Ast.h"
#include "Diagnostic.h"

#include <string_view>

namespace rs::lang {

struct ParseResult {
    Document document;
    Diagnostics diagnostics;
};

// Reads a whole program file. Every line with an error is reported (with the
// line and column of the offending token) and left out of the document; the
// lines around it are still read.
ParseResult parse(std::string_view source);

// Parentheses an expression may nest. Far beyond any real program, and small
// enough that every walker of the syntax tree (printer, checks, code
// generator, ladder conversion and layout) recurses well inside the stack,
// also under AddressSanitizer. A chain such as a + b + c is one node with
// many children, however long, so it does not count.
inline constexpr int kMaxExpressionDepth = 100;

} // namespace rs::lang
