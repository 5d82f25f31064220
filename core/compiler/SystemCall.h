// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "SystemInstruction.h"
#include "lang/Ast.h"
#include "lang/Diagnostic.h"

#include <map>
#include <optional>
#include <vector>

// A call of a system instruction in the project text: a ";@system NAME
// OPERAND="…" …" record in a step (docs/file-format.md), as a system block's
// expansion writes it (docs/block-libraries.md). The language has no call
// syntax, so the call is a record: a comment to every other reader.
namespace rs::compiler {

inline constexpr const char* kSystemRecord = "system";

struct SystemCall {
    const SystemInstruction* instruction = nullptr;
    // One per parameter, in the instruction's order: a variable (its name
    // resolved) or a number, each at its place in the record.
    std::vector<lang::Value> arguments;
    lang::SourceLocation location; // of the record
};

// Whether the line is a ;@system record (a well-formed one).
bool isSystemRecord(const lang::Line& line);

// The call a ;@system record of unit `station` makes, its names resolved as
// the unit's statements' are. Nothing when the line holds none, or when the
// call is wrong: an unknown instruction or operand, an operand given twice
// or not at all, one that is no variable or number, or of a kind the
// operand does not take (each an error in `diagnostics` at its column).
std::optional<SystemCall> readSystemCall(const lang::Document& document, int station,
                                         const lang::Line& line, lang::Diagnostics& diagnostics);

// The calls of one unit's code, by the line that holds each.
using SystemCalls = std::map<const lang::Line*, SystemCall>;

} // namespace rs::compiler
