// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "BlockInstance.h"
#include "BlockLibrary.h"
#include "lang/Ast.h"

#include <map>
#include <set>
#include <string>
#include <vector>

// Make Block…: a block of the library format drafted from statements of a
// unit, and the instance that stands for them. What the statements read
// becomes an input pin, what they write an output pin; a memory they write
// that nothing else in the unit uses becomes a private variable, recorded
// at the same address, so that the instance's expansion is the statements
// themselves.
namespace rs::blocks {

struct BlockDraft {
    BlockDefinition block;  // name, pins, private variables, timers and body
    BlockInstance instance; // each pin bound to the operand it stands for
    // What each pin and private variable stands for, by the name it has.
    std::map<std::string, lang::Address> addresses;
    std::string refusal; // why the statements cannot make a block; empty when they can
};

// `lines`: the statements to make the block of (comments are dropped);
// `usedElsewhere`: the addresses the rest of the unit's code uses;
// `names`: pin and private names chosen for addresses, instead of the ones
// made from the operands (a name, or an address such as I0_12).
BlockDraft draftBlock(const std::string& blockName, const std::vector<lang::Line>& lines,
                      const std::set<lang::Address>& usedElsewhere,
                      const std::map<lang::Address, std::string>& names = {});

// Every address the statements among the lines read or write.
std::set<lang::Address> addressesIn(const std::vector<lang::Line>& lines);

} // namespace rs::blocks
