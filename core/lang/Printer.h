// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Ast.h"

#include <string>
#include <vector>

namespace rs::lang {

// Column (1-based) where trailing comments start, as in the manuals' examples.
inline constexpr int kCommentColumn = 32;

// The canonical text of a document: upper-case keywords and addresses, one
// statement per line, comments kept and aligned. Printing a parsed canonical
// text gives the same text back.
std::string print(const Document& document);
// The same with the preamble and each unit's declarations given apart, for a
// writer that adds lines to them without copying the units' code.
// `expectedSize`: room kept for the text at once (a large project's text
// grown by doubling touched twice its size).
std::string print(const std::vector<Line>& preamble, const std::vector<UnitProgram>& units,
                  const std::vector<std::vector<Line>>& declarations, std::size_t expectedSize = 0);

std::string printStatement(const Statement& statement);
std::string printExpression(const Expr& expr);
std::string printOperand(const Operand& operand);
std::string printValue(const Value& value);
// What an assignment does to its target, as written after it: "++", "+= 2", "= R0.1 * 3".
std::string printAssignmentOperation(const Assignment& assignment);
std::string printDeclaration(const Declaration& declaration);

// Hundredths of a second in the language's notation: 510 -> "5s10".
std::string formatTime(int hundredths);

} // namespace rs::lang
