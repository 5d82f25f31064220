// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "Program.h"
#include "lang/Diagnostic.h"

#include <optional>
#include <string>
#include <string_view>

// Rungsmith's text form of a PL110 program (docs/pl110.md): reading with an
// error per bad line at its line and column, and the canonical printing.
// Reading the printed text gives back the tree that printed it.
namespace rs::pl110 {

struct ProgramReading {
    Program program;
    lang::Diagnostics diagnostics; // errors drop their line; every other line is read
};

// Limits: 1 MB of text; a condition nests at most 64 groups deep.
ProgramReading readProgram(std::string_view text);

std::string printProgram(const Program& program);

// One rung as its line is written, "Q1 = I1 * /I2 ; comment", with the
// program's declared names: what the ladder's rung dialog reads. Errors are
// on line 1.
struct RungReading {
    std::optional<Line> line; // a Rung line, when it reads
    lang::Diagnostics diagnostics;
};
RungReading readRung(const Program& program, std::string_view text);
// Part of a condition, "I3", "/I3 * (VW1 >= 10)", "NOT": what the ladder
// puts in series or in parallel.
struct ConditionReading {
    std::optional<Circuit> circuit;
    lang::Diagnostics diagnostics;
};
ConditionReading readCondition(const Program& program, std::string_view text);
// The line as the printer writes it within a program.
std::string printRungLine(const Line& line);
// A condition or part of one as a rung's line writes it: "I1 * /I2".
std::string printCondition(const Circuit& circuit);

// Whether a file's text is a PL110 program: its first directive is "$target PL110".
bool isPl110Text(std::string_view text);

// The canonical spellings the printer uses, for whoever shows a program's
// parts (the ladder's boxes, messages).
std::string operandText(const Operand& operand); // the name, or the address
std::string valueText(const Value& value);
std::string_view compareWord(CompareOp op);     // "<>"
std::string_view formulaWord(FormulaOp op);     // "<<"
std::string_view timeBaseWord(TimeBase base);   // "100ms"
std::string_view timerWord(TimerType type);     // "TONR"
std::string_view counterWord(CounterType type); // "MDOWN"
std::string_view inputWord(CounterInput input); // "RESET"

// The words a name may not be: the text form's keywords.
bool isKeyword(std::string_view word);

} // namespace rs::pl110
