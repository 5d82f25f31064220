// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "BlockLibrary.h"

#include <cstdint>
#include <optional>
#include <string>
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

// A name of the library format (library, block, pin, private variable): a
// letter, then letters, digits and '_'.
bool isLibraryName(std::string_view name);

// A decimal integer written canonically (no '+', no leading zeros, no "-0").
std::optional<std::int64_t> canonicalInteger(std::string_view text);

// A time constant as defaults and bindings write it: 0s00 .. 655s35, seconds
// without leading zeros, hundredths two digits.
bool isTimeConstant(std::string_view text);

// A state code as `state` records write it: 16# and four hex digits, either
// case on reading, upper case on writing (16#8001 is 0x8001).
std::optional<int> stateCodeOf(std::string_view word);
std::string stateCodeWord(int code);

} // namespace rs::blocks
