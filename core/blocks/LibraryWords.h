// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "BlockLibrary.h"

#include <optional>
#include <string_view>
#include <vector>

// The words a library file spells its enumerations with, one table for the
// reader, the writer and the command line, so they can never disagree.
namespace rs::blocks {

std::string_view wordOf(BlockKind kind);
std::string_view wordOf(PinDirection direction);
std::string_view wordOf(PinKind kind);
std::string_view wordOf(PinRole role);
std::string_view wordOf(OperandKind kind);
std::string_view wordOf(PrivateKind kind);

std::optional<BlockKind> blockKindOf(std::string_view word);
std::optional<PinDirection> pinDirectionOf(std::string_view word);
std::optional<PinKind> pinKindOf(std::string_view word);
std::optional<PinRole> pinRoleOf(std::string_view word);
std::optional<OperandKind> operandKindOf(std::string_view word);
std::optional<PrivateKind> privateKindOf(std::string_view word);

// The operand kinds a pin of this kind and direction can take at all; a
// pin's own list is a subset of it. In the order of the enum.
std::vector<OperandKind> possibleOperands(PinKind kind, PinDirection direction);

} // namespace rs::blocks
